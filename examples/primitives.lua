-- primitives.lua: every primitive of the script API on a 4 × 2 grid, each
-- with its own colour. The camera frames the grid by itself: the script
-- returns a solid, not a scene.

local function colour(r, g, b) return {color={r, g, b}} end

local shapes = {
  sphere{r=8}:material(colour(0.8, 0.2, 0.2)),
  ellipsoid{radii={10, 6, 4}}:material(colour(0.9, 0.5, 0.1)),
  box{size={14, 14, 14}, center=true}:material(colour(0.9, 0.8, 0.2)),
  cylinder{r=7, h=16, center=true}:material(colour(0.3, 0.7, 0.3)),
  cone{r=8, h=16, center=true}:material(colour(0.2, 0.6, 0.8)),
  cylinder{r1=8, r2=4, h=14, center=true}:material(colour(0.3, 0.3, 0.9)),
  -- A sphere cut by a half-space: the flat face is the plane z = 2.
  (sphere{r=8} * half_space{normal={0, 0, 1}, offset=2}):material(colour(0.6, 0.3, 0.8)),
  -- A quadric: the hyperboloid of one sheet x² + y² - z² <= 16, cut to a box.
  (quadric{matrix={{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, -16}}}
    * box{size={20, 20, 16}, center=true}):material(colour(0.8, 0.3, 0.6)),
}

local grid = {}
for i, s in ipairs(shapes) do
  local column, row = (i - 1) % 4, (i - 1) // 4
  grid[i] = s:translate(column * 24, -row * 24, 0)
end
return union(grid)
