-- Seed 001, 3.3: a Warn spot light. The cone of half-angle 20° lights a
-- disc of radius h·tan 20° on the floor; within it the light falls off as
-- cos^8 of the angle off the axis.
local floor = plane{normal={0, 0, 1}}:material{color={0.85, 0.85, 0.8}, ambient=0.03}

local part = (box{size={1.6, 1.6, 1.2}, center=true} - cylinder{r=0.5, h=2, center=true})
  :translate(0, 0, 0.6)
  :material{color={0.3, 0.5, 0.8}, specular=0.4, shininess=40}

return scene{
  objects = {floor, part},
  camera = camera{eye={0, -9, 6}, look_at={0, 0, 0.4}, fov=45},
  lights = {spot_light{pos={1.5, -1.5, 7}, look_at={0, 0, 0}, angle=20, exponent=8, intensity=1.1},
            point_light{pos={-6, -6, 8}, intensity=0.08}},
  background = {0.01, 0.01, 0.02},
}
