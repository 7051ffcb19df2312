-- door_wedge.lua: a door stop from one linear_extrude. The footprint is a
-- rounded rectangle from y = 0 to y = length; scale={1, 0} squeezes y to
-- nothing at the top, so the back (at y = 0) stays upright and the top
-- folds onto a ridge along x: a wedge, its slope a ruled face, exact in
-- the render. Grooves across the slope give the foot a grip, and a hole
-- through the back hangs it on a nail.
--   csgray render examples/door_wedge.lua -o wedge.png
--   csgray export examples/door_wedge.lua -o wedge.stl
local width  = width or 40     -- across the door's gap
local length = length or 120   -- from the upright back to the tip
local height = height or 25    -- of the upright back
local round  = round or 4      -- radius of the footprint's corners

local footprint = rectangle{size={width, length}}:translate(-width / 2, 0)
  :offset{r=-round}:offset{r=round}
local wedge = linear_extrude{footprint, height=height, scale={1, 0}}

-- The slope falls from the ridge (y = 0, z = height) to the tip
-- (y = length, z = 0); each groove is a bar across it, sunk 1.2 deep.
local slope = math.deg(math.atan(height, length))
local grooves = {}
for i = 1, 5 do
  local y = length * (0.25 + 0.12 * i)
  local z = height * (1 - y / length)
  grooves[#grooves + 1] = box{size={width + 2, 3, 3}, center=true}
    :rotate(slope, 0, 0):translate(0, y, z)
end
local hole = cylinder{d=5, h=width + 2, center=true}:rotate(0, 90, 0):translate(0, 6, 6)
return (wedge - union(table.unpack(grooves)) - hole)
  :material{color={0.85, 0.45, 0.2}, specular=0.2, shininess=15}
