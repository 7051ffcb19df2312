-- print_in_place.lua: a hinge printed in one piece that moves, as printed.
-- Two leaves with knuckles about one axis along y: the outer knuckles and
-- the pin through them are one leaf, the middle knuckle, bored out around
-- the pin, the other. Nothing of one leaf touches the other: `csgray check`
-- counts two pieces (docs/check.md, "shells") and warns of no cut,
-- although each lies within the other's reach.
--
--   csgray export examples/print_in_place.lua -o hinge.3mf
--   csgray check examples/print_in_place.lua

local r, pin_r = 3, 1.5            -- knuckle and pin radius
local clear = clearance or 0.5     -- between the moving parts
local width, leaf = 20, 25         -- along the axis; each leaf's reach
local middle = {width / 3 + clear / 2, 2 * width / 3 - clear / 2}

-- A knuckle from y0 to y1 about the axis (x = 0, z = r).
local function knuckle(radius, y0, y1)
  return cylinder{r=radius, h=y1 - y0}:rotate(-90, 0, 0):translate(0, y0, r)
end
-- A leaf 2 thick from the axis out to x = side * (leaf + r), reaching in to
-- the axis only where its own knuckles are.
local function plate(side, spans)
  local x0 = side > 0 and r + clear or -(leaf + r + clear)
  local parts = {box{size={leaf, width, 2}}:translate(x0, 0, 0)}
  for _, s in ipairs(spans) do
    local tab_x = side > 0 and 0 or -(r + clear)
    parts[#parts + 1] = box{size={r + clear, s[2] - s[1], 2}}:translate(tab_x, s[1], 0)
  end
  return union(table.unpack(parts))
end

local outer = {{0, middle[1] - clear}, {middle[2] + clear, width}}
local fixed = plate(-1, outer) + knuckle(r, outer[1][1], outer[1][2])
              + knuckle(r, outer[2][1], outer[2][2]) + knuckle(pin_r, 0, width)
local moving = plate(1, {middle}) + knuckle(r, middle[1], middle[2])
               - knuckle(pin_r + clear, middle[1] - 1, middle[2] + 1)

local hinge = fixed + moving
local report = check(hinge, {samples=20000, grid=64})
assert(report.ok, report.summary)
for _, w in ipairs(report.warnings) do
  assert(w.kind ~= "separate shells", w.message)
end

return scene{
  objects = {fixed:material{color={0.35, 0.55, 0.75}, specular=0.3},
             moving:material{color={0.85, 0.55, 0.25}, specular=0.3}},
  camera  = camera{eye={-40, -45, 45}, look_at={0, 10, 2}, fov=40},
}
