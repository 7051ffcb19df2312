-- Seed 001, chapter 3: a glass sphere that refracts, beside a mirror
-- sphere, over a checkerboard floor.
local floor = plane{normal={0, 0, 1}}
  :material{color=checker{size=1, colors={{0.9, 0.9, 0.9}, {0.15, 0.15, 0.2}}}}

local glass = sphere{r=1}:translate(-1.2, 0, 1)
  :material{color={1, 1, 1}, ambient=0, diffuse=0.05, specular=0.8, shininess=200,
            transparency=0.95, ior=1.5, fresnel=true}

local mirror = sphere{r=1}:translate(1.2, 1.5, 1)
  :material{color={0.9, 0.9, 0.9}, ambient=0.02, diffuse=0.1, specular=0.6, shininess=100,
            reflection=0.85}

return scene{
  objects = {floor, glass, mirror},
  camera = camera{eye={0, -7, 3}, look_at={0, 0.5, 0.8}, fov=50},
  lights = {point_light{pos={-4, -6, 8}, intensity=0.9},
            point_light{pos={6, -2, 5}, intensity=0.4}},
  background = {0.55, 0.7, 0.9},
}
