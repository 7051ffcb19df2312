-- tinted_glass.lua: coloured glass that is darker where it is thicker, as
-- Hall's illumination model has it. With filter_distance, a stretch of
-- glass d long passes filter^(d / filter_distance) of the light: the three
-- panes are one glass, 0.5, 1 and 2 thick, and the ball is darkest through
-- its middle. A lamp behind the ball shows through it as a highlight
-- (transmitted_specular).
--   csgray render examples/tinted_glass.lua -o glass.png
local floor = plane{normal={0, 0, 1}}
  :material{color=checker{size=1, colors={{0.9, 0.9, 0.9}, {0.3, 0.3, 0.35}}}}

local glass = {color={1, 1, 1}, ambient=0, diffuse=0.02, specular=0.6, shininess=60,
               transparency=0.92, filter={0.3, 0.75, 0.4}, filter_distance=1,
               ior=1.5, fresnel=true, transmitted_specular=1}

local objects = {floor}
for i, thickness in ipairs{0.5, 1, 2} do
  objects[#objects + 1] = box{size={1.6, thickness, 2.4}}
    :translate(-4.4 + 2.2 * (i - 1), 1 - thickness / 2, 0):material(glass)
end
objects[#objects + 1] = sphere{r=1.1}:translate(3.0, 0.6, 1.1):material(glass)

return scene{
  objects = objects,
  camera = camera{eye={0, -9, 2.4}, look_at={0, 0.5, 0.6}, fov=55},
  lights = {point_light{pos={-5, -7, 9}, intensity=0.9},
            point_light{pos={4.5, 5.3, 0.9}, intensity=1.5}},
  background = {0.55, 0.7, 0.9},
}
