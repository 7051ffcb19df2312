-- A coupling flange with six dowel pins pressed through it: the flange is
-- swept from a 2D profile with a bore and six holes on a bolt circle, and
-- each pin, a cylinder of the hole's radius, is turned into place about
-- the flange's axis. For export each hole is cut into its pin's own
-- polygon, and the walls the two share are made flush, so the mesh is
-- one solid with no crevice round the pins
-- (docs/cli.md, "Contacts").
--   csgray render examples/dowel_flange.lua -o dowel_flange.png
--   csgray export examples/dowel_flange.lua -o dowel_flange.stl
local radius, bore, thickness = 30, 10, 6
local pins, pin_radius, bolt_circle, pin_length = 6, 3, 21, 14
local profile = circle(radius) - circle(bore)
local dowels = {}
for i = 0, pins - 1 do
  local turn = i * 360 / pins + 15
  profile = profile - circle(pin_radius):translate(bolt_circle, 0):rotate(turn)
  dowels[#dowels + 1] = cylinder{r = pin_radius, h = pin_length}
    :translate(bolt_circle, 0, -4):rotate(0, 0, turn)
end
local flange = linear_extrude{profile, height = thickness}
local part = (flange + union(table.unpack(dowels))):translate(0, 0, 4)
return scene{
  objects = {part:material{color = {0.72, 0.62, 0.42}, specular = 0.5, shininess = 40},
             plane{}:material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {55, -70, 60}, look_at = {0, 0, 6}, up = {0, 0, 1}, fov = 40},
  lights = {point_light{pos = {80, -60, 120}, intensity = 1},
            point_light{pos = {-90, -40, 70}, intensity = 0.4}},
}
