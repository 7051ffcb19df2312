-- rounded_box.lua: a box with rounded edges and corners, written the way
-- people write it without hull or minkowski: three boxes, twelve edge
-- cylinders and eight corner spheres, each tangent to its neighbours. The
-- exact render is smooth; the export joins the tangent parts into one
-- closed mesh (docs/cli.md, "Contacts").
--   csgray render examples/rounded_box.lua -o rounded_box.png
--   csgray export examples/rounded_box.lua -o rounded_box.stl

local x, y, z = size_x or 40, size_y or 30, size_z or 20
local r = radius or 3

local parts = {
  box{size={x, y - 2 * r, z - 2 * r}}:translate(0, r, r),
  box{size={x - 2 * r, y, z - 2 * r}}:translate(r, 0, r),
  box{size={x - 2 * r, y - 2 * r, z}}:translate(r, r, 0),
}
local xs, ys, zs = {r, x - r}, {r, y - r}, {r, z - r}
for _, cx in ipairs(xs) do
  for _, cy in ipairs(ys) do
    for _, cz in ipairs(zs) do parts[#parts + 1] = sphere{r=r}:translate(cx, cy, cz) end
  end
end
for _, cy in ipairs(ys) do   -- edges along x
  for _, cz in ipairs(zs) do
    parts[#parts + 1] = cylinder{r=r, h=x - 2 * r}:rotate(0, 90, 0):translate(r, cy, cz)
  end
end
for _, cx in ipairs(xs) do   -- edges along y
  for _, cz in ipairs(zs) do
    parts[#parts + 1] = cylinder{r=r, h=y - 2 * r}:rotate(-90, 0, 0):translate(cx, r, cz)
  end
end
for _, cx in ipairs(xs) do   -- edges along z
  for _, cy in ipairs(ys) do
    parts[#parts + 1] = cylinder{r=r, h=z - 2 * r}:translate(cx, cy, r)
  end
end

return scene{
  objects = {union(parts):material{color={0.3, 0.55, 0.8}, specular=0.5, shininess=50}},
  camera = camera{eye={x * 2.2, -y * 2.0, z * 3.2}, look_at={x / 2, y / 2, z / 2}, fov=35},
  lights = {point_light{pos={x * 3, -y * 2, z * 6}}, point_light{pos={-x, y * 2, z * 3}, intensity=0.4}},
  background = {0.92, 0.92, 0.94},
}
