-- rounded_enclosure.lua: a box for a small board, rounded outside and
-- inside, and the lid that drops onto it, lifted off to show its lip.
-- rounded_box{} makes the shells (exact: faces, quarter cylinders along
-- the edges and spheres at the corners, exported as one mesh), and
-- minkowski() rounds the lip's ring the way OpenSCAD parts do.
--   csgray render examples/rounded_enclosure.lua -o rounded_enclosure.png
--   csgray export examples/rounded_enclosure.lua -o rounded_enclosure.3mf

local x, y, z = size_x or 60, size_y or 40, size_z or 24
local wall = wall or 2
local r = radius or 4        -- outer rounding
local gap = gap or 0.3       -- clearance between the lip and the wall
local lid_t = 3              -- lid thickness

assert(r > wall and 2 * r < math.min(x, y, z), "radius must exceed the wall and fit the box")

-- The body: a rounded box less one a wall smaller, open at the top.
local outer = rounded_box{size={x, y, z}, r=r}
local cavity = rounded_box{size={x - 2 * wall, y - 2 * wall, z}, r=r - wall}:translate(wall, wall, wall)
local body = (outer - cavity):material{color={0.25, 0.45, 0.7}, specular=0.4, shininess=40}

-- The lid: a plate whose edges are rounded over its whole thickness (r is
-- half of it), and under it a lip that fits the cavity: a box summed with
-- a ball is a rounded box, less a smaller box to leave a ring.
local plate = rounded_box{size={x, y, lid_t}, r=lid_t / 2}
local lip_r = 1
local lip_x, lip_y = x - 2 * (wall + gap), y - 2 * (wall + gap)
local lip_outer = minkowski(box{size={lip_x - 2 * lip_r, lip_y - 2 * lip_r, 4}}, sphere(lip_r))
                    :translate(wall + gap + lip_r, wall + gap + lip_r, -4)
local lip = lip_outer - box{size={lip_x - 2 * 1.5, lip_y - 2 * 1.5, 10}}:translate(wall + gap + 1.5, wall + gap + 1.5, -8)
local lid = (plate + lip):material{color={0.85, 0.85, 0.8}, specular=0.3, shininess=30}
             :translate(0, 0, z + 15)

return scene{
  objects = {body, lid},
  camera  = camera{eye={x * 2.0, -y * 2.8, z * 3.2}, look_at={x / 2, y / 2, z * 0.7}, fov=40},
  lights  = {point_light{pos={x * 3, -y * 2, z * 6}}, point_light{pos={-x, y * 2, z * 3}, intensity=0.4}},
  background = {0.92, 0.92, 0.94},
}
