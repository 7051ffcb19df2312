-- A coaster with a raised checkerboard: one linear_extrude of the dark
-- squares, which meet only at their corners. Meshed as one polygon set,
-- such a region meets itself at every shared corner; the export takes the
-- extrusion apart into the squares' extrusions and joins them there as
-- solids that touch along an edge (docs/cli.md, "Contacts").
--   csgray export examples/checker_coaster.lua -o coaster.stl --stats
local n, cell, rim = n or 6, cell or 12, rim or 4
local side = n * cell + 2 * rim
local squares = {}
for i = 0, n - 1 do
  for j = 0, n - 1 do
    if (i + j) % 2 == 0 then
      squares[#squares + 1] = square(cell):translate(rim + i * cell, rim + j * cell)
    end
  end
end
local base = rounded_box{size = {side, side, 4}, r = 2}
local checkers = linear_extrude{union(table.unpack(squares)), height = 1.5}:translate(0, 0, 4)
return base + checkers
