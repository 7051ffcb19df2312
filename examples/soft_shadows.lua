-- Seed 000, 17.2.4: area lights. A rectangular light and a spherical one,
-- sampled with 8×8 and 6×6 shadow rays per point, give soft shadows whose
-- penumbra widens with the distance from the object to the floor.
local floor = plane{normal={0, 0, 1}}:material{color={0.8, 0.8, 0.8}, ambient=0.08}

local low = box{size={1.2, 1.2, 0.5}, center=true}:translate(-1.6, 0, 0.25)
  :material{color={0.8, 0.5, 0.2}}
local high = sphere{r=0.7}:translate(1.4, 0.3, 2.2):material{color={0.3, 0.6, 0.4}, specular=0.3}
local post = cylinder{r=0.08, h=2.2}:translate(1.4, 0.3, 0):material{color={0.5, 0.5, 0.5}}

return scene{
  objects = {floor, low, high, post},
  camera = camera{eye={0, -9, 5.5}, look_at={0, 0.3, 0.7}, fov=45},
  lights = {area_light{pos={-2.5, -3.5, 5}, u={1.5, 0, 0}, v={0, 1.5, 0}, samples=64, intensity=0.75},
            sphere_light{pos={5, -3, 4}, r=0.6, samples=36, intensity=0.35}},
  background = {0.1, 0.1, 0.12},
}
