-- function_graph.lua: a ripple, z = f(x, y), as a printable tile: the
-- solid under the graph down to a flat base. The triangles are refined
-- where the ripple bends until they lie within `tolerance` of it, so the
-- crests get small triangles and the flat rim large ones.
--   csgray render examples/function_graph.lua -o ripple.png
local height = height or 6  -- crest height above the rim (mm)
local ripple = graph{
  f = function(x, y)
    local r = math.sqrt(x * x + y * y)
    return height * math.cos(r / 3) * math.exp(-r / 12)
  end,
  x = {-30, 30}, y = {-30, 30},
  resolution = 16, tolerance = 0.05, base = -8,
}
return scene{
  objects = {ripple:material{color = "steelblue", specular = 0.4, shininess = 30}},
  camera = camera{eye = {70, -90, 70}, look_at = {0, 0, -2}, up = {0, 0, 1}, fov = 40},
}
