-- superellipsoid.lua: the family of superellipsoids in a chart, e across
-- the columns (the shape of the sections across z: square, round, diamond)
-- and n along the rows (the profile along z), and in front a soap dish cut
-- from one: a soft-edged block, hollowed by a flatter one, with drain
-- slots. Every face is exact in the render; the export meshes each within
-- the tolerance.
--   csgray render examples/superellipsoid.lua -o superellipsoid.png
--   csgray export examples/superellipsoid.lua -o superellipsoid.stl

local exponents = {0.1, 0.5, 1, 2}
local parts = {}
for row, n in ipairs(exponents) do
  for column, e in ipairs(exponents) do
    local hue = (column - 1) / 3
    parts[#parts + 1] = superellipsoid{radii=1, e=e, n=n}
      :translate(2.6 * column - 13, 2.6 * row - 6.5, 1)
      :material{color={0.85 - 0.5 * hue, 0.35 + 0.2 * hue, 0.2 + 0.6 * hue},
                specular=0.5, shininess=60}
  end
end

-- The dish: the upper half of a 12 × 8 × 6 superellipsoid whose edges are
-- rounded (e = n = 0.3), hollowed by a rounder one whose bottom is 0.8
-- above the dish's, three slots through the floor.
local outer = superellipsoid{radii={6, 4, 3}, e=0.3, n=0.3}
local hollow = superellipsoid{radii={5.2, 3.2, 2.4}, e=0.4, n=0.5}:translate(0, 0, 3.2)
local slots = {}
for i = -1, 1 do
  slots[#slots + 1] = box{size={6, 0.5, 4}, center=true}:translate(0, 1.2 * i, 0)
end
local dish = (outer * half_space{normal={0, 0, -1}, offset=0} - hollow - union(slots))
  :translate(5.5, 0, 0)
  :material{color={0.9, 0.9, 0.86}, specular=0.3, shininess=30}

local slab = rectangle{size={34, 24}}:translate(-16, -12, 0)
  :material{color={0.5, 0.52, 0.55}, ambient=0.15, diffuse=0.85}

return scene{
  objects    = {dish, slab, table.unpack(parts)},
  camera     = camera{eye={0, -17, 22}, look_at={0, 1.5, 0}, fov=55},
  lights     = {point_light{pos={-12, -16, 22}, color={1, 0.97, 0.92}},
                point_light{pos={16, 2, 12}, color={0.3, 0.32, 0.4}}},
  background = {0.12, 0.13, 0.18},
}
