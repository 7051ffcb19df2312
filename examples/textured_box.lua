-- Seed 000, 17.2.3: textures. A box wrapped in a bitmap (box mapping), a
-- marble sphere, a wooden cylinder and a turbulent floor, each placed with
-- the texture's own scale.
local bricks = image_texture{file="textures/bricks.png", mapping="box", scale=1}
local crate = box{size={2, 2, 2}, center=true}:translate(-1.8, 0, 1)
  :material{color=bricks, specular=0.1}

local stone = sphere{r=1}:translate(0.8, -0.4, 1)
  :material{color=marble{colors={{0.92, 0.92, 0.9}, {0.25, 0.25, 0.3}}, scale=0.4},
            specular=0.6, shininess=80}

local log = cylinder{r=0.6, h=2.2}:rotate(0, 0, 30):translate(2.8, 1.4, 0)
  :material{color=wood{scale=0.15, strength=3}}

local floor = plane{normal={0, 0, 1}}
  :material{color=turbulence{colors={{0.35, 0.4, 0.3}, {0.7, 0.72, 0.6}}, scale=0.7}}

return scene{
  objects = {floor, crate, stone, log},
  camera = camera{eye={0, -8, 4.5}, look_at={0.4, 0.4, 0.9}, fov=50},
  lights = {point_light{pos={-4, -6, 8}, intensity=0.9}, point_light{pos={6, -3, 4}, intensity=0.3}},
  background = {0.6, 0.7, 0.85},
}
