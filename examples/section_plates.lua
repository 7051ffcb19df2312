-- section_plates.lua: a part drawn by its sections, as OpenSCAD's
-- projection() makes them. A ball with three tapered bores is cut at five
-- heights (projection(s, {cut=true})); each section becomes a thin plate
-- put back at its height, and the ball's shadow (projection(s)) is the
-- base they stand over.
--   csgray render examples/section_plates.lua -o plates.png
--   csgray export examples/section_plates.lua -o plates.stl
local r = r or 12          -- the ball's radius
local layers = layers or 5 -- how many sections
local bore = cylinder{r1=r / 2.4, r2=r / 4.8, h=2.5 * r, center=true}
local part = sphere(r) - bore - bore:rotate(90, 0, 0) - bore:rotate(0, 90, 0)

local plates = {}
for i = 1, layers do
  local z = r * (2 * i / (layers + 1) - 1)
  -- The section at height z: the part moved down so that z is at 0.
  local section = projection(part:translate(0, 0, -z), {cut=true})
  plates[#plates + 1] = linear_extrude{section, height=0.6, center=true}:translate(0, 0, z)
end
local base = linear_extrude{projection(part):offset{r=1}, height=1}:translate(0, 0, -r - 2)
plates[#plates + 1] = base
return scene{objects={union(plates):material{color={0.85, 0.55, 0.2}}},
             camera=camera{eye={34, -42, 27}, look_at={0, 0, -2}}}
