-- Refraction and mirrors: a glass lens (two balls intersected) and a glass
-- box less a ball, before a mirror ball, over a checkerboard, two point
-- lights, rays followed to depth 8. The render benchmark of secondary
-- rays against POV-Ray (bench/povray/glass.pov is the same scene).
local glass = {color = {1, 1, 1}, diffuse = 0.05, transparency = 0.95, ior = 1.5}
local lens = (sphere{r = 4}:translate(0, 0, -3) * sphere{r = 4}:translate(0, 0, 3))
  :rotate(90, 0, 0):translate(-4, 0, 3):material(glass)
local cup = (box{size = {5, 5, 5}, center = true} - sphere{r = 3}:translate(0, 0, 2))
  :translate(4, 1, 2.5):material(glass)
local mirror = sphere{r = 3}:translate(1, 9, 3):material{color = {0.9, 0.9, 0.9}, diffuse = 0.1,
                                                          reflection = 0.9}
local floor = plane{}:material{color = checker{size = 2, colors = {{0.9, 0.9, 0.9}, {0.2, 0.2, 0.25}}}}
return scene{
  objects = {floor, lens, cup, mirror},
  camera = camera{eye = {0, -22, 12}, look_at = {0, 2, 2}, up = {0, 0, 1}, fov = 50},
  lights = {point_light{pos = {20, -20, 40}, intensity = 1},
            point_light{pos = {-30, -10, 20}, intensity = 0.5}},
  max_depth = 8,
}
