-- Seed 001, chapter 2: a sphere over a parallelogram floor, lit by one
-- point light, with Phong highlights (2.2.2) and its hard shadow (2.3).
local floor = parallelogram{origin={-4, -3, 0}, u={8, 0, 0}, v={1.5, 7, 0}}
  :material{color={0.75, 0.7, 0.6}, ambient=0.15, diffuse=0.85}

local ball = sphere{r=1}:translate(0, 0.5, 1.4)
  :material{color={0.8, 0.15, 0.1}, ambient=0.1, diffuse=0.8, specular=0.5, shininess=60}

return scene{
  objects = {floor, ball},
  camera = camera{eye={1, -8, 4}, look_at={0.3, 0.5, 0.8}, fov=45},
  lights = {point_light{pos={-3, -4, 7}}},
  background = {0.1, 0.1, 0.15},
}
