-- rounded_slot.lua: a mounting plate with rounded corners and two
-- adjustment slots, written as OpenSCAD parts write them: minkowski() of
-- a box and a cylinder for the plate, hull() of two cylinders for each
-- slot. Both are exact here (a box plus a cylinder along its side is the
-- box's outline grown by the radius, extruded; the hull of two cylinders
-- side by side is the hull of their circles, extruded), so the slots'
-- ends are true half cylinders, in the render and in the export alike.
--   csgray render examples/rounded_slot.lua -o rounded_slot.png

local x, y, t = size_x or 80, size_y or 50, thickness or 6
local corner = corner or 6   -- radius of the plate's corners
local slot_r = slot_r or 3   -- half the slot's width
local travel = travel or 20  -- length of the slot between its centres

local plate = minkowski(box{size={x - 2 * corner, y - 2 * corner, t / 2}},
                        cylinder{r=corner, h=t / 2}):translate(corner, corner, 0)

local function slot(cx, cy)
  local end_ = cylinder{r=slot_r, h=t + 2}
  return hull(end_, end_:translate(travel, 0, 0)):translate(cx - travel / 2, cy, -1)
end

-- A capsule handle on top: the hull of two equal spheres, exact.
local handle = hull(sphere(3):translate(x / 2 - 12, y / 2, t), sphere(3):translate(x / 2 + 12, y / 2, t))

-- A label pad with cut corners: the 2D Minkowski sum of a rectangle and
-- an octagon (convex, one a polygon: the hull of octagons at the
-- rectangle's corners), extruded.
local pad = linear_extrude{minkowski(square{size={12, 8}}, regular_polygon{n=8, r=2}), height=1.5}
  :translate(5, y / 2 - 4, t)

-- A corner guard: an L of straight edges, not convex, grown by an octagon
-- (the L moved, each of its edges swept over the octagon), extruded.
local L = square{size={16, 3}} + square{size={3, 12}}
local guard = linear_extrude{minkowski(L, regular_polygon{n=8, r=1}), height=2}
  :translate(x - 22, 5, t)

local part = difference(plate + handle + pad + guard, {slot(x / 2, y * 0.2), slot(x / 2, y * 0.8)})
return scene{
  objects = {part:material{color={0.7, 0.72, 0.75}, specular=0.6, shininess=60}},
  camera  = camera{eye={x * 1.2, -y * 1.6, 70}, look_at={x / 2, y / 2, 0}, fov=40},
  lights  = {point_light{pos={x * 2, -y * 2, 120}}, point_light{pos={-x, y * 2, 60}, intensity=0.4}},
  background = {0.92, 0.92, 0.94},
}
