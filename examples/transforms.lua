-- transforms.lua: every transform on the same L-shaped block with a hole,
-- on a grid read like text: as built, translated up, rotated by x, y, z
-- angles, rotated about an axis, scaled non-uniformly, mirrored, and
-- sheared by a general affine matrix.

local block = (box{size={8, 8, 4}} + box{size={4, 8, 12}})
  - cylinder{r=1.5, h=10, center=true}:translate(6, 4, 2)

local variants = {
  block,
  block:translate(0, 0, 4),
  block:rotate(0, 0, 45),
  block:rotate{angle=60, axis={1, 1, 0}},
  block:scale(1.5, 0.75, 1),
  block:mirror(1, 0, 0):translate(8, 0, 0),
  -- x' = x + 0.5 z: a shear, rows of the 3×4 matrix [linear | offset].
  block:transform{{1, 0, 0.5, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}},
}

local colours = {{0.8, 0.8, 0.8}, {0.9, 0.4, 0.3}, {0.9, 0.7, 0.2}, {0.4, 0.8, 0.4},
                 {0.3, 0.7, 0.9}, {0.5, 0.4, 0.9}, {0.9, 0.4, 0.8}}
local grid = {}
for i, v in ipairs(variants) do
  local column, row = (i - 1) % 4, (i - 1) // 4
  grid[i] = v:material{color=colours[i]}:translate(column * 17, -row * 20, 0)
end
return union(grid)
