-- 200 lens parts on a plane: each two balls ∩ a cylinder (a lens with a
-- flat rim) less an ellipsoid through its middle, turned at random about
-- x and then z; two point lights with shadows. The render benchmark of
-- nested quadric intersections and differences against POV-Ray
-- (bench/povray/lens_field.pov is the same scene; both draw the turns
-- from the same Lehmer sequence, seed 12345, so the parts match).
local seed = 12345
local function random()
  seed = (seed * 16807) % 2147483647
  return seed / 2147483647
end
local lens = sphere{r = 3}:translate(0, 0, -2) * sphere{r = 3}:translate(0, 0, 2)
             * cylinder{r = 2, h = 4, center = true}
             - ellipsoid{radii = {0.8, 0.8, 1.5}}
local parts = {}
for i = 0, 19 do
  for j = 0, 9 do
    local ax, az = 360 * random(), 360 * random()
    parts[#parts + 1] = lens:rotate(ax, 0, 0):rotate(0, 0, az):translate(6 * i, 6 * j, 2.5)
  end
end
return scene{
  objects = {union(table.unpack(parts)):material{color = {0.3, 0.5, 0.8}, specular = 0.4, shininess = 30},
             plane{}:material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {57, -40, 60}, look_at = {57, 27, 0}, up = {0, 0, 1}, fov = 60},
  lights = {point_light{pos = {120, -50, 150}, intensity = 1},
            point_light{pos = {-50, -20, 80}, intensity = 0.5}},
}
