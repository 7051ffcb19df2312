-- mobius_strip.lua: a parametric surface that does not close up, the
-- Möbius strip: parametric{..., surface=true} gives it as an open sheet
-- of triangles. Its ends meet with a half turn (f puts the points of
-- u = 2π where those of u = 0 are, turned over), so the strip has one side
-- and one edge; it is shaded smooth across the seam all the same.
--   csgray render examples/mobius_strip.lua -o mobius.png
local radius = radius or 20  -- of the strip's middle line
local width = width or 12
local strip = parametric{
  f = function(u, v)
    local r = radius + v * math.cos(u / 2)
    return {r * math.cos(u), r * math.sin(u), v * math.sin(u / 2)}
  end,
  u = {0, 2 * math.pi}, v = {-width / 2, width / 2},
  resolution = {96, 8}, surface = true,
}
return scene{
  objects = {
    strip:material{color = "teal", specular = 0.4, shininess = 30},
    plane{normal = {0, 0, 1}, offset = -12}:material{color = "wheat"},
  },
  lights = {point_light{pos = {-40, -60, 90}, intensity = 1}},
  camera = camera{eye = {0, -70, 45}, look_at = {0, 0, -2}, up = {0, 0, 1}, fov = 50},
}
