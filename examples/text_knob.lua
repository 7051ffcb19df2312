-- text_knob.lua: a knob with its name embossed on the top and a scale
-- engraved into it (docs/script.md, "Text"). The letters keep the font's
-- curves: their sides are the surfaces the Bézier curves sweep.
--   csgray render examples/text_knob.lua -o text_knob.png
--   csgray export examples/text_knob.lua -o text_knob.stl
--   csgray check examples/text_knob.lua

local R, H = radius or 15, height or 10
local font = "DejaVu Sans:style=Bold"

local body = cylinder{r=R, h=H}
local name = text{"csgray", size=5, font=font, halign="center", valign="center"}
local embossed = linear_extrude{name, height=1}:translate(0, 2, H)
local scale = text{"1 2 3 4", size=3, font=font, halign="center", valign="center"}
local engraved = linear_extrude{scale, height=1.2}:translate(0, -6, H - 1)

return scene{
  objects = {(body + embossed - engraved):material{color={0.55, 0.3, 0.2}, specular=0.5, shininess=50}},
  camera = camera{eye={18, -38, 42}, look_at={0, 0, 6}, fov=40},
  lights = {point_light{pos={40, -60, 90}}, point_light{pos={-40, 30, 60}, intensity=0.4}},
}
