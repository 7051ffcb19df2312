-- Seed 001, 3.3: a Warn spot light. The cone of half-angle 20° lights a
-- disc of radius h·tan 20° on the floor; within it the light falls off as
-- cos^8 of the angle off the axis. Beside it a warm spot with a soft edge
-- (POV-Ray's radius and falloff): full light within 6°, fading to none at
-- 16°.
local floor = plane{normal={0, 0, 1}}:material{color={0.85, 0.85, 0.8}, ambient=0.03}

local part = (box{size={1.6, 1.6, 1.2}, center=true} - cylinder{r=0.5, h=2, center=true})
  :translate(0, 0, 0.6)
  :material{color={0.3, 0.5, 0.8}, specular=0.4, shininess=40}

return scene{
  objects = {floor, part},
  camera = camera{eye={0, -9, 6}, look_at={0, 0, 0.4}, fov=45},
  lights = {spot_light{pos={1.5, -1.5, 7}, look_at={0, 0, 0}, angle=20, exponent=8, intensity=1.1},
            spot_light{pos={-3, 2, 7}, look_at={-3, 3, 0}, angle=16, inner=6, exponent=0,
                       color={1, 0.8, 0.55}, intensity=0.7},
            point_light{pos={-6, -6, 8}, intensity=0.08}},
  background = {0.01, 0.01, 0.02},
}
