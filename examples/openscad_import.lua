-- openscad_import.lua: a part from OpenSCAD's .csg file, used as any solid.
-- The file's $fn = 6 cylinder stays a hexagon; its round hole and the
-- letters engraved on its side (OpenSCAD's text, Liberation Sans) are exact.
--   csgray render examples/openscad/nut_block.csg -o block.png   (the file alone)
--   csgray export examples/openscad_import.lua -o blocks.stl
local block = import_csg{file="openscad/nut_block.csg"}
-- Two of them side by side on a plate.
local plate = box{size={50, 24, 2}, center=true}:translate(0, 0, -6)
return plate + block:translate(-12, 0, 0) + block:translate(12, 0, 0)
