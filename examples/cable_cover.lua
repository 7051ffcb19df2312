-- A cable cover: a half pipe with two flanges, screwed to a wall. The
-- halves come from whole cylinders cut by a box exactly as wide as the
-- pipe, as OpenSCAD habit has it: the box's sides touch the outer
-- cylinder along two lines and its bottom along a third. The exported
-- mesh keeps no slivers of the cylinder's facets past those sides
-- (docs/cli.md, "Contacts": a flat cutter whose sides graze the part).
local length, outer, wall = 80, 12, 2.5
local pipe = cylinder{r = outer, h = length} - cylinder{r = outer - wall, h = length + 2}:translate(0, 0, -1)
-- Everything with y < 0 goes: x from -outer to outer, y from -outer to 0.
local half = pipe - box{size = {2 * outer, outer, length + 2}}:translate(-outer, -outer, -1)
local flanges = {}
for _, side in ipairs({-1, 1}) do
  -- Into the pipe's wall, so that flange and pipe are one solid.
  local flange = box{size = {10 + wall, wall, length}}
                   :translate(side > 0 and outer - wall or -outer - 10, 0, 0)
  for _, z in ipairs({12, length - 12}) do
    flange = flange - cylinder{r = 2, h = 3 * wall}:rotate(-90, 0, 0)
                        :translate(side * (outer + 5), -wall, z)
  end
  flanges[#flanges + 1] = flange
end
-- On the wall (the xz plane turned to the floor), the pipe along x.
return union(half, table.unpack(flanges)):rotate(90, 0, 0):rotate(0, 0, 90)
