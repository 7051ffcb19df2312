-- blob.lua: a grip for a 10 mm rod, modelled as a blob, balls whose
-- fields melt into one smooth shape (POV-Ray's blob). Eleven balls along
-- the grip swell it towards the palm, three of negative strength press
-- finger grooves into its underside, and the rod's bore is an ordinary
-- cylinder subtracted from it.
--   csgray render examples/blob.lua -o blob.png
--   csgray export examples/blob.lua -o blob.stl

local length = grip_length or 110   -- mm
local balls = {}
for i = 0, 10 do
  local x = length * (i / 10 - 0.5)
  local swell = 1 + 0.2 * math.sin(math.pi * i / 10)   -- thickest in the middle
  balls[#balls + 1] = {center={x, 0, 0}, r=20 * swell, strength=1}
end
for i = -1, 1 do
  balls[#balls + 1] = {center={length * 0.2 * i, -20, -3}, r=14, strength=-0.4}
end

local grip = blob{threshold=0.5, balls=balls}
local bore = cylinder{r=5, h=length + 80, center=true}:rotate(0, 90, 0)
local part = (grip - bore):material{color={0.2, 0.35, 0.3}, specular=0.3, shininess=20}

return scene{
  objects    = {part, plane{}:translate(0, 0, -25):material{color={0.85, 0.85, 0.82}}},
  camera     = camera{eye={150, -120, 60}, look_at={0, 0, -6}, fov=45},
  lights     = {point_light{pos={-150, -200, 250}, color={1, 0.97, 0.92}},
                point_light{pos={200, 60, 80}, color={0.3, 0.32, 0.4}}},
  background = {0.12, 0.13, 0.18},
}
