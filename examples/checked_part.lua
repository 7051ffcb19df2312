-- checked_part.lua: a part that tests its own booleans. check() makes the
-- export in memory and holds it against the exact model (docs/check.md);
-- a script, or a test of your own, can assert on what it finds.
--
--   csgray render examples/checked_part.lua -o out/checked.png
--   csgray check examples/checked_part.lua

local base = box{size={60, 40, 8}}
local boss = cylinder{r=9, h=10}:translate(30, 20, 4)      -- starts inside the base
local bore = cylinder{r=5, h=30}:translate(30, 20, -5)   -- runs through: no shared faces
local holes = {}
for i, x in ipairs({8, 52}) do
  holes[i] = cylinder{r=2.5, h=20}:translate(x, 20, -5)
end
local part = difference(base + boss, bore, holes)

local report = check(part, {samples=20000, grid=64})
assert(report.ok, report.summary)
-- The booleans are clean: no operands share or touch faces.
for _, w in ipairs(report.warnings) do
  assert(w.kind ~= "coincident faces" and w.kind ~= "touching faces", w.message)
end
-- The volume the rays measure agrees with the formula to a tenth of a percent:
-- the base and the boss above it, less the bore and the two holes.
local pi = math.pi
local expected = 60 * 40 * 8 + pi * 9^2 * 6 - pi * 5^2 * 14 - 2 * pi * 2.5^2 * 8
assert(math.abs(report.volume.exact - expected) < 1e-3 * expected,
       ("volume %.1f, expected %.1f"):format(report.volume.exact, expected))

return scene{
  objects = {part:material{color={0.35, 0.55, 0.75}, specular=0.3}},
  camera  = camera{eye={90, -60, 70}, look_at={30, 20, 4}, fov=40},
}
