-- An 8 × 8 chart of superellipsoids (radius 1, 2.5 apart), e from 0.1 to
-- 2 across the columns and n along the rows, on a plane, two point lights
-- with shadows: the render benchmark of superellipsoids against POV-Ray
-- (bench/povray/superellipsoids.pov is the same scene).
local parts = {}
for i = 0, 7 do
  for j = 0, 7 do
    local e, n = 0.1 + 1.9 * i / 7, 0.1 + 1.9 * j / 7
    parts[#parts + 1] = superellipsoid{radii = 1, e = e, n = n}:translate(2.5 * i, 2.5 * j, 1)
  end
end
return scene{
  objects = {union(table.unpack(parts)):material{color = {0.3, 0.5, 0.8}, specular = 0.4, shininess = 30},
             plane{}:material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {8.75, -14, 16}, look_at = {8.75, 8.75, 0}, up = {0, 0, 1}, fov = 60},
  lights = {point_light{pos = {40, -20, 60}, intensity = 1},
            point_light{pos = {-20, -10, 30}, intensity = 0.5}},
}
