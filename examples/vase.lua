-- vase.lua: a vase turned from 40 stacked cone frustums (each frustum's top
-- radius is the next one's bottom radius), hollowed by a similar stack 2
-- thinner, with a torus lip. The frustums stand face to face; the export
-- joins them along their shared rims.
--   csgray render examples/vase.lua -o vase.png
--   csgray export examples/vase.lua -o vase.stl

local layers = layers or 40
local height = 80
local wall = 2
local step = height / layers
-- The silhouette: the radius at the bottom of layer i.
local function radius(i) return 20 + 6 * math.sin(i * 10 / layers) end

local outer, inner = {}, {}
for i = 0, layers - 1 do
  outer[#outer + 1] = cylinder{r1=radius(i), r2=radius(i + 1), h=step}:translate(0, 0, step * i)
  inner[#inner + 1] = cylinder{r1=radius(i) - wall, r2=radius(i + 1) - wall, h=step}
    :translate(0, 0, step * (i + 1))
end
local lip = torus{R=radius(layers) - wall / 2, r=wall / 2}:translate(0, 0, step * layers)
local vase = difference(union(outer), union(inner)) + lip

return scene{
  objects = {vase:material{color={0.25, 0.5, 0.45}, specular=0.6, shininess=80}},
  camera = camera{eye={110, -140, 120}, look_at={0, 0, 38}, fov=35},
  lights = {point_light{pos={150, -150, 250}}, point_light{pos={-100, 50, 100}, intensity=0.4}},
  background = {0.95, 0.93, 0.9},
}
