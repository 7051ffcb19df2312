-- turned_vase.lua: a vase turned from its profile. The wall is a polygon
-- in the (radius, height) plane, from the axis up the outside and back
-- down the inside to the floor; a circle on its rim makes a rounded lip.
-- rotate_extrude turns it about z: the polygon's edges become cones and
-- rings, the circle a torus, all exact.
--   csgray export examples/turned_vase.lua -o vase.stl
local height = height or 80
local wall   = wall or 2
local n      = 40             -- points up each side of the wall

local function radius(z) return 18 + 7 * math.sin(z / 14) + 4 * (z / height) ^ 2 end
local points = {{0, 0}}
for k = 0, n do
  local z = height * k / n
  points[#points + 1] = {radius(z), z}
end
for k = n, 0, -1 do
  local z = wall + (height - wall) * k / n
  points[#points + 1] = {radius(z) - wall, z}
end
points[#points + 1] = {0, wall}
local lip = circle{d=wall + 1}:translate(radius(height) - wall / 2, height)
local vase = rotate_extrude{polygon{points=points} + lip}
return vase:material{color={0.3, 0.5, 0.8}, specular=0.5, shininess=40}
