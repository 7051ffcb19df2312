-- height_map.lua: a terrain tile from a file of heights, OpenSCAD's
-- surface(). height_maps/hill.dat holds 9 rows of 13 heights (the first
-- row at y = 0); the solid stands on a flat base and is scaled to 48 × 32.
-- A PNG image works the same way: its grey levels are the heights.
--   csgray render examples/height_map.lua -o hill.png
local hill = height_map{file="height_maps/hill.dat", center=true}
return hill:scale(4, 4, 3)
