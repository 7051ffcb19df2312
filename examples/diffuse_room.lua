-- diffuse_room.lua: light bouncing between surfaces. A room of a red, a
-- green and three white walls, lit by a glowing panel in the ceiling and a
-- small lamp; the white walls pick up the coloured ones' light, the
-- corners darken, and a brushed-metal ball (gloss) shows a blurred room.
-- The walls are open surfaces, so an export holds the ball and the block.
--   csgray render examples/diffuse_room.lua -o room.png --samples 4
local samples = samples or 8  -- rays scattered from each visible point
local white = {color = {0.75, 0.75, 0.75}, diffuse = 0.9}
local function wall(origin, u, v, look)
  return parallelogram{origin = origin, u = u, v = v}:material(look)
end
return scene{
  objects = {
    wall({-5, -5, 0}, {10, 0, 0}, {0, 10, 0}, white),                             -- floor
    wall({-5, -5, 10}, {10, 0, 0}, {0, 10, 0}, white),                            -- ceiling
    wall({-5, 5, 0}, {10, 0, 0}, {0, 0, 10}, white),                              -- back
    wall({-5, -5, 0}, {0, 10, 0}, {0, 0, 10}, {color = {0.7, 0.1, 0.1}}),         -- left
    wall({5, -5, 0}, {0, 10, 0}, {0, 0, 10}, {color = {0.1, 0.6, 0.15}}),         -- right
    wall({-1.5, -1.5, 9.99}, {3, 0, 0}, {0, 3, 0}, {color = {1, 1, 1}, diffuse = 0, ambient = 0,
                                                    emission = {4, 3.8, 3.4}}),   -- glowing panel
    sphere(2):translate(-1.8, 1, 2):material{color = {0.9, 0.9, 0.9}, diffuse = 0.1,
                                            reflection = 0.8, gloss = 0.15},
    box{size = {3, 3, 5}}:rotate(0, 0, 25):translate(1.5, -1, 0):material(white),
  },
  camera = camera{eye = {0, -16, 5}, look_at = {0, 0, 4.5}, fov = 45},
  lights = {point_light{pos = {0, -2, 9}, intensity = 0.3}},
  indirect = {samples = samples, bounces = 2},
}
