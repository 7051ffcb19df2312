-- fractal_landscape.lua: a landscape made by midpoint displacement on
-- triangles, over a lake: the mountain is an open surface
-- (fractal_mountain{..., surface=true}: no block under it, shaded smooth),
-- the lake a still, transparent plane at the water line (z = −10) through
-- which the valleys under water show. The same seed gives the same
-- landscape; change it for another. Nothing here is a solid, so there is
-- nothing to export.
--   csgray render examples/fractal_landscape.lua -o landscape.png
local seed = seed or 7
local land = fractal_mountain{size = 100, levels = 6, roughness = 0.55, seed = seed, surface = true}
return scene{
  objects = {
    land:material{color = "olivedrab", diffuse = 0.85},
    plane{normal = {0, 0, 1}, offset = -10}
      :material{color = "royalblue", transparency = 0.4, reflection = 0.3},
  },
  lights = {point_light{pos = {-80, -120, 200}, intensity = 1}},
  camera = camera{eye = {160, -90, 90}, look_at = {50, 50, -5}, up = {0, 0, 1}, fov = 45},
}
