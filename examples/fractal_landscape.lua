-- fractal_landscape.lua: a mountain made by midpoint displacement on
-- triangles, with a lake: a still, transparent plane at the water line (z = −10).
-- The same seed gives the same mountain; change it for another. The lake
-- is an open surface, so an export holds the mountain alone.
--   csgray render examples/fractal_landscape.lua -o landscape.png
local seed = seed or 7
local mountain = fractal_mountain{size = 100, levels = 6, roughness = 0.55, seed = seed}
return scene{
  objects = {
    mountain:material{color = "olivedrab", diffuse = 0.85},
    plane{normal = {0, 0, 1}, offset = -10}
      :material{color = "royalblue", transparency = 0.4, reflection = 0.3},
  },
  lights = {point_light{pos = {-80, -120, 200}, intensity = 1}},
  camera = camera{eye = {160, -90, 90}, look_at = {50, 50, -5}, up = {0, 0, 1}, fov = 45},
}
