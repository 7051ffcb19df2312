-- dxf_flange.lua: a flange plate from a DXF drawing. The drawing's layer
-- "outline" is the plate (a polyline whose corners are arcs: bulges), its
-- layer "holes" four bolt holes (circles) and a slot (two arcs and two
-- lines, joined end to end). Arcs stay exact arcs, so the holes are true
-- cylinders in the render and in the export.
--   csgray render examples/dxf_flange.lua -o flange.png
--   csgray export examples/dxf_flange.lua -o flange.stl
local drawing = "drawings/flange.dxf"
local outline = import_dxf{file=drawing, layer="outline"}
local holes = import_dxf{file=drawing, layer="holes"}
local plate = linear_extrude{outline - holes, height=thickness or 4}
-- A collar around each hole: the holes grown by 3 (within the plate), less
-- the holes.
local collar = linear_extrude{holes:offset{r=3} * outline - holes, height=8}
return plate + collar
