-- dxf_vent_grille.lua: a vent grille from a DXF drawing. The layer
-- "outline" is the plate; the layer "slots" holds one INSERT of the block
-- "slot" (a rounded slot: two lines and two half circles) as an array of
-- 4 columns 27 apart and 4 rows 12 apart, as CAD programs write a
-- rectangular array of one shape: sixteen slots, each an exact arc at its
-- ends.
--   csgray render examples/dxf_vent_grille.lua -o grille.png
--   csgray export examples/dxf_vent_grille.lua -o grille.stl
local drawing = "drawings/vent_grille.dxf"
local plate = import_dxf{file=drawing, layer="outline"}
local slots = import_dxf{file=drawing, layer="slots"}
-- Each slot is 16 × 5 with half circles of radius 2.5 at its ends.
local slot = 16 * 5 + math.pi * 2.5 ^ 2
assert(math.abs(slots:area() - 16 * slot) < 1e-6, "the array makes sixteen slots")
return linear_extrude{plate - slots, height=thickness or 3}
