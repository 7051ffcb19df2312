-- night_light.lua: a scene lit by its glowing parts alone. lights={}
-- names no lamp, so none is added beside the camera either: the glowing
-- ring lights the floor, the block and the post by indirect light, and
-- their far sides stay dark.
--   csgray render examples/night_light.lua -o night.png --samples 4
local samples = samples or 32 -- rays scattered from each visible point
local glow = {color = {1, 1, 1}, diffuse = 0, ambient = 0, specular = 0, emission = {6, 3.6, 1.5}}
local matte = function(color) return {color = color, ambient = 0, specular = 0.1} end
return scene{
  objects = {
    parallelogram{origin = {-8, -8, 0}, u = {16, 0, 0}, v = {0, 16, 0}}:material(matte{0.8, 0.8, 0.8}),
    torus{R = 1.6, r = 0.3}:translate(0, 0, 1.5):material(glow),
    box{size = {1.6, 1.6, 1.6}}:rotate(0, 0, 20):translate(-4, 0.5, 0):material(matte{0.3, 0.5, 0.9}),
    cylinder{r = 0.6, h = 3}:translate(3.5, 1.5, 0):material(matte{0.9, 0.9, 0.9}),
  },
  camera = camera{eye = {0, -11, 6}, look_at = {0, 0, 1}, fov = 55},
  background = {0, 0, 0},
  lights = {},
  indirect = {samples = samples, bounces = 1},
}
