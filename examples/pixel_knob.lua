-- pixel_knob.lua: a knob with a letter N cut into its top from square
-- pixels. The diagonal pixels touch only along an edge: the cut goes
-- through there, so the export stays a 2-manifold (docs/cli.md,
-- "Contacts").
--   csgray export examples/pixel_knob.lua -o pixel_knob.stl

local glyph = {
  "X...X",
  "XX..X",
  "X.X.X",
  "X..XX",
  "X...X",
}
local p = pixel or 2     -- pixel size
local depth = depth or 1

local knob = cylinder{r=15, h=10}
local pixels = {}
for row, line in ipairs(glyph) do
  for col = 1, #line do
    if line:sub(col, col) == "X" then
      pixels[#pixels + 1] = box{size={p, p, 2 * depth}}
        :translate((col - 3.5) * p, (2.5 - row) * p, 10 - depth)
    end
  end
end

return scene{
  objects = {(knob - union(pixels)):material{color={0.8, 0.3, 0.2}, specular=0.4, shininess=40}},
  camera = camera{eye={25, -35, 45}, look_at={0, 0, 5}, fov=40},
  lights = {point_light{pos={40, -60, 90}}, point_light{pos={-40, 30, 60}, intensity=0.4}},
}
