-- modifiers.lua: OpenSCAD's modifier characters as methods. A plate with
-- a counterbored hole: the cutter is highlighted (OpenSCAD's #) so that
-- the render shows where it cuts; a bolt is a ghost (%), drawn see-through
-- but left out of the export and the check; a label plate is disabled (*).
--   csgray render examples/modifiers.lua -o modifiers.png
--   csgray export examples/modifiers.lua -o plate.stl   (the plate alone)
local plate = box{size={40, 30, 6}, center=true}
local hole = cylinder{d=6.4, h=10, center=true}
local counterbore = cylinder{d=11, h=4}  -- from the middle to above the top
local cutter = (hole + counterbore):highlight()

local bolt = (cylinder{d=6, h=20} + cylinder{d=10, h=3}:translate(0, 0, 20))
  :translate(0, 0, -14):ghost()
local label = box{size={20, 2, 4}, center=true}:translate(0, -16, 0):disable()

return plate - cutter + bolt + label
