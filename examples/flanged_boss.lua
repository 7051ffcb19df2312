-- A flanged boss: a tube standing in a square flange with rounded corners
-- and four bolt holes. The flange is swept from a 2D profile whose middle
-- is a hole of the tube's outer radius, so the two solids meet all round
-- the tube, face to face on a circle. The flange's circle and the tube's
-- are cut into the same polygon for export (docs/cli.md, "Contacts"), so
-- the mesh is one solid with no crevice between them.
--   csgray render examples/flanged_boss.lua -o flanged_boss.png
--   csgray export examples/flanged_boss.lua -o flanged_boss.stl
local radius, bore, height = 12, 8, 30
local side, corner, thickness = 60, 8, 5
local plate = square{size = {side - 2 * corner, side - 2 * corner}, center = true}:offset{r = corner}
local profile = plate - circle(radius)
for _, x in ipairs({-1, 1}) do
  for _, y in ipairs({-1, 1}) do
    profile = profile - circle(3.2):translate(x * (side / 2 - 9), y * (side / 2 - 9))
  end
end
local flange = linear_extrude{profile, height = thickness}
local tube = cylinder{r = radius, h = height} - cylinder{r = bore, h = height + 2}:translate(0, 0, -1)
return (flange + tube):material{color = {0.55, 0.6, 0.68}}
