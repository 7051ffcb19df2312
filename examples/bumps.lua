-- Bumps (POV-Ray's normal { bumps }): any texture's brightness taken as a
-- height over the surface, bump_depth high, tilts the normal as the raised
-- surface's would be tilted, while the shape stays exact and smooth (see
-- the round silhouettes and the shadows). A hammered bowl of copper, a
-- ball of frosted glass with ripples of wood rings, and a floor of stone.
local stone = plane{}:material{color={0.55, 0.53, 0.5}, bumps=turbulence{scale=0.4}, bump_depth=0.03}

local bowl = (sphere{r=1.6} - sphere{r=1.45} - box{size={4, 4, 2}, center=true}:translate(0, 0, 1))
  :scale(1, 1, 0.7):translate(-1.9, 0, 1.12)
  :material{color={0.85, 0.45, 0.25}, specular=0.8, shininess=80, reflection=0.15,
            bumps=perlin{scale=0.12}, bump_depth=0.02}

local ball = sphere{r=1}:translate(1.6, 0.3, 1)
  :material{color={0.95, 0.97, 1}, transparency=0.85, ior=1.5, fresnel=true, specular=0.7,
            shininess=120, bumps=wood{scale=0.15, strength=0}, bump_depth=0.01}

return scene{
  objects = {stone, bowl, ball},
  camera = camera{eye={0, -7, 3.8}, look_at={-0.2, 0, 0.7}, fov=45},
  lights = {point_light{pos={-5, -6, 9}, intensity=0.9}, point_light{pos={6, -2, 4}, intensity=0.3}},
  background = {0.25, 0.3, 0.4},
}
