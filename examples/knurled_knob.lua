-- knurled_knob.lua: a knob whose top edge is rounded by a torus fillet,
-- with 24 knurl grooves (cylinders) that end exactly on the line where the
-- fillet meets the side, tangentially. The torus's outer equator and the
-- side's rim are the same polygon in the export, so the grooves cut
-- through a clean edge there (docs/cli.md, "Contacts").
--   csgray render examples/knurled_knob.lua -o knurled_knob.png
--   csgray export examples/knurled_knob.lua -o knurled_knob.stl

local R, H, f = radius or 15, height or 12, fillet or 2
local grooves_count = grooves or 24

local body = cylinder{r=R, h=H - f} + cylinder{r=R - f, h=H}
  + torus{R=R - f, r=f}:translate(0, 0, H - f)
local cuts = {}
for i = 0, grooves_count - 1 do
  cuts[#cuts + 1] = cylinder{r=0.6, h=H - f}:translate(R, 0, 0):rotate(0, 0, i * 360 / grooves_count)
end

return scene{
  objects = {(body - union(cuts)):material{color={0.35, 0.4, 0.5}, specular=0.6, shininess=60}},
  camera = camera{eye={30, -45, 40}, look_at={0, 0, 5}, fov=40},
  lights = {point_light{pos={50, -60, 90}}, point_light{pos={-40, 30, 60}, intensity=0.4}},
}
