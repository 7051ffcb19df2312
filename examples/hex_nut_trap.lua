-- hex_nut_trap.lua: a clamp block with a captive nut. A bolt hole goes
-- through it; a hexagonal pocket holds the nut, and a slot of the nut's
-- width lets it slide in from the side. The pocket and the slot are 2D
-- regions extruded: exact flats, no facets.
--   csgray export examples/hex_nut_trap.lua -o trap.stl -D flats=13 -D bolt=8
local bolt      = bolt or 3          -- M3: the bolt's diameter
local flats     = flats or 5.5       -- the nut's width across flats (M3: 5.5)
local nut_h     = nut_h or 2.4       -- the nut's height
local clearance = clearance or 0.3   -- what the printer needs around a part

local size = 4 * flats
local block = box{size={size, size, 3 * nut_h + 6}, center=true}
local hole = cylinder{d=bolt + clearance, h=size, center=true}
-- regular_polygon{n=6, flats=} has a corner on +x and flats facing ±y,
-- so a slot along +x of the same width takes the nut.
local nut = regular_polygon{n=6, flats=flats + clearance}
local slot = rectangle{size={size, flats + clearance}}:translate(0, -(flats + clearance) / 2)
local pocket = linear_extrude{nut + slot, height=nut_h + clearance, center=true}

local part = (block - hole - pocket):material{color={0.9, 0.5, 0.2}, specular=0.3, shininess=20}
-- Seen from the side the slot opens to.
return scene{objects={part}, camera=camera{eye={60, -40, 30}, look_at={0, 0, 0}}}
