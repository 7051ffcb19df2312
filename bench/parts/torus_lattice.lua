-- A 20 × 20 lattice of tori (R = 2, r = 0.5, 5 apart) lying on a plane,
-- two point lights with shadows: the render benchmark of tori against
-- POV-Ray (bench/povray/torus_lattice.pov is the same scene).
local tori = {}
for i = 0, 19 do
  for j = 0, 19 do
    tori[#tori + 1] = torus{R = 2, r = 0.5}:translate(5 * i, 5 * j, 0.5)
  end
end
return scene{
  objects = {union(table.unpack(tori)):material{color = {0.8, 0.5, 0.3}, specular = 0.4, shininess = 30},
             plane{}:material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {47.5, -40, 45}, look_at = {47.5, 40, 0}, up = {0, 0, 1}, fov = 60},
  lights = {point_light{pos = {100, -50, 150}, intensity = 1},
            point_light{pos = {-50, -20, 80}, intensity = 0.5}},
}
