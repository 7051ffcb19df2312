-- diamond_knurl.lua: a knob with a diamond knurl, cut by 48 grooves
-- (thin cylinders) slanted 30° one way and the other. Each groove's axis
-- meets those of the other hand's, so grooves of one radius cross with
-- their surfaces tangent where they meet; the export makes every groove
-- that crosses another a thousandth of the tolerance wider, which it
-- cuts at once (docs/cli.md, "Contacts").
--   csgray render examples/diamond_knurl.lua -o diamond_knurl.png
--   csgray export examples/diamond_knurl.lua -o diamond_knurl.stl

local R = radius or 15      -- [10:30] knob radius, mm
local H = height or 18      -- [10:30] knob height, mm
local count = grooves or 24 -- [8:36] grooves of each hand
local groove = cylinder{r=0.7, h=3 * H, center=true}

local grooves = {}
for i = 0, count - 1 do
  for _, hand in ipairs({-1, 1}) do
    grooves[#grooves + 1] = groove:rotate(hand * 30, 0, 0):translate(R, 0, H / 2)
                                  :rotate(0, 0, i * 360 / count)
  end
end
local knob = cylinder{r=R, h=H} - union(grooves) - cylinder{d=6, h=3 * H, center=true}

return scene{
  objects = {knob:material{color={0.75, 0.6, 0.3}, specular=0.7, shininess=80}},
  camera = camera{eye={2.6 * R, -3.2 * R, 2.6 * H}, look_at={0, 0, H / 2}, fov=35},
  lights = {point_light{pos={3 * R, -4 * R, 6 * H}, intensity=1},
            point_light{pos={-4 * R, -R, 3 * H}, intensity=0.4}},
}
