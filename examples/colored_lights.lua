-- Seed 001, 2.4: coloured lights. Red, green and blue point lights add up
-- to white where all three reach; each solid casts three coloured shadows.
-- falloff=true divides each light by the squared distance (seed 001, 2.2.1).
local floor = plane{normal={0, 0, 1}}:material{color={0.9, 0.9, 0.9}, ambient=0.05}

local post = cylinder{r=0.4, h=2.5}:material{color={0.9, 0.9, 0.9}, specular=0.3}
local ball = sphere{r=0.8}:translate(2, 1.2, 0.8):material{color={0.95, 0.95, 0.95}, specular=0.5}

local function lamp(x, y, color)
  return point_light{pos={x, y, 6}, color=color, intensity=40, falloff=true}
end

return scene{
  objects = {floor, post, ball},
  camera = camera{eye={0, -9, 6}, look_at={0.6, 0.4, 0.6}, fov=45},
  lights = {lamp(-3, -2, {1, 0, 0}), lamp(3, -2, {0, 1, 0}), lamp(0, 3, {0, 0, 1})},
  background = {0.02, 0.02, 0.03},
}
