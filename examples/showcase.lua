-- showcase.lua: a mounting plate with four bosses, through-holes, a
-- counterbored centre, a spherical dimple and a slot, on a ground slab.
-- Render it with:  csgray render examples/showcase.lua -o out/showcase.png

local length, width, thickness = 100, 70, 8   -- mm, Z up

local plate = box{size={length, width, thickness}}

-- Bosses on the top face, and the holes through bosses and plate.
local corners = {{15, 15}, {length - 15, 15}, {15, width - 15}, {length - 15, width - 15}}
local bosses, holes = {}, {}
for i, c in ipairs(corners) do
  -- (from a millimetre inside the plate: faces that merely touch would
  -- make csgray check warn)
  bosses[i] = cylinder{r=8, h=11}:translate(c[1], c[2], thickness - 1)
  holes[i] = cylinder{d=6, h=40}:translate(c[1], c[2], -10)
end

-- A counterbored hole in the middle: a wide shallow bore over a narrow one.
local centre = {length / 2, width / 2}
local counterbore = cylinder{r=12, h=10}:translate(centre[1], centre[2], thickness - 3)
local bore = cylinder{r=5, h=40}:translate(centre[1], centre[2], -10)

-- A spherical dimple and a rounded slot (two cylinders and a box).
local dimple = sphere{r=9}:translate(20, width / 2, thickness + 5)
local slot = union(
  cylinder{r=4, h=40}:translate(72, 20, -10),
  cylinder{r=4, h=40}:translate(72, 50, -10),
  box{size={8, 30, 40}}:translate(68, 20, -10))

local part = difference(union(plate, union(bosses)), union(holes), counterbore, bore, dimple, slot)
part = part:material{color={0.75, 0.45, 0.15}}

-- The ground is an open surface: it is rendered, but not exported.
local ground = rectangle{size={400, 400}}:translate(-150, -165, 0)
               :material{color={0.35, 0.4, 0.45}}

return scene{
  objects    = {part, ground},
  camera     = camera{eye={150, -80, 110}, look_at={50, 35, 0}, fov=40},
  lights     = {point_light{pos={160, -120, 220}, color={1, 0.95, 0.9}},
                point_light{pos={-80, 60, 160}, color={0.3, 0.35, 0.45}}},
  background = {0.2, 0.2, 0.3},
}
