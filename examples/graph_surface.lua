-- graph_surface.lua: the graph of a function as a sheet, not a solid:
-- graph{..., surface=true} gives the surface z = f(x, y) alone, open at
-- its edges and shaded smooth from f's derivatives. A saddle rises on
-- two sides and falls on the others, so the camera sees its top on one
-- side and its underside on the other, lit by a second light below.
--   csgray render examples/graph_surface.lua -o saddle.png
local depth = depth or 12  -- how far the saddle rises and falls at the edges
local saddle = graph{
  f = function(x, y) return depth * (x * x - y * y) / 900 end,
  x = {-30, 30}, y = {-30, 30},
  resolution = 24, tolerance = 0.05, surface = true,
}
return scene{
  objects = {
    saddle:material{color = "darkorange", specular = 0.5, shininess = 40},
    plane{normal = {0, 0, 1}, offset = -25}
      :material{color = checker{size = 10, colors = {"white", "slategray"}}},
  },
  lights = {
    point_light{pos = {-60, -80, 120}, intensity = 1},
    point_light{pos = {90, 20, -12}, intensity = 0.6},
  },
  camera = camera{eye = {75, -70, 22}, look_at = {0, 0, -4}, up = {0, 0, 1}, fov = 45},
}
