-- torus.lua: tori of every kind on a slab. A ring with a quarter cut away
-- (showing the round section of the tube), two linked rings, a ring bored
-- through six times, and a spindle torus (R < r), whose tube overlaps
-- itself across the axis: an apple with dimples at the poles.
-- Render it with:  csgray render examples/torus.lua -o out/torus.png

local function colour(r, g, b)
  return {color={r, g, b}, ambient=0.12, diffuse=0.8, specular=0.4, shininess=40}
end

-- A ring lying flat, a quarter of it cut away by a box.
local cut = difference(torus{R=3, r=1}, box{size={5, 5, 3}}:translate(0, 0, -1.5))
  :translate(-7, 1.5, 1):material(colour(0.85, 0.45, 0.15))

-- Two linked rings: one standing in the xz plane, the other lying in the
-- xy plane with its centre on the first one's core circle.
local standing = torus{R=2.2, r=0.5}:rotate(90, 0, 0)
local lying = torus{R=2.2, r=0.5}:translate(2.2, 0, 0)
local chain = union(standing, lying):rotate(0, -20, 15):translate(-1.2, 3, 2.8)
  :material(colour(0.75, 0.75, 0.8))

-- A ring with six vertical holes through its tube.
local holes = {}
for i = 1, 6 do
  holes[i] = cylinder{r=0.55, h=4, center=true}:translate(2.5, 0, 0):rotate(0, 0, 60 * i)
end
local bored = difference(torus{R=2.5, r=0.9}, union(holes))
  :translate(6.5, 1.5, 0.9):material(colour(0.2, 0.55, 0.8))

-- A spindle torus: the apple.
local apple = torus{R=0.9, r=1.6}:translate(1, -4.5, 1.4 * 1):material(colour(0.8, 0.15, 0.12))

-- The slab is an open surface: rendered, not exported (the tori touch it).
local slab = rectangle{size={28, 20}}:translate(-14, -9, 0)
  :material{color={0.55, 0.55, 0.5}, ambient=0.15, diffuse=0.85}

return scene{
  objects    = {cut, chain, bored, apple, slab},
  camera     = camera{eye={1, -20, 12}, look_at={0, 0.5, 0.8}, fov=52},
  lights     = {point_light{pos={-10, -14, 18}, color={1, 0.97, 0.92}},
                point_light{pos={14, 4, 10}, color={0.3, 0.32, 0.4}}},
  background = {0.12, 0.13, 0.18},
}
