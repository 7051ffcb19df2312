-- povray_room.lua: a room made as POV-Ray users make one, a single box
-- with the camera and a lamp inside it. The camera sees the box's inner
-- faces, and the lamp lights them: a solid stops light only where a ray
-- crosses its surface. A mirror ball and a glass ball stand on the floor.
-- (docs/povray.md)
--   csgray render examples/povray_room.lua -o room.png --samples 4
local room = box{size={10, 10, 5}, center=true}:translate(0, 0, 2.5)
  :material{color=checker{size=1, colors={"white", "lightsteelblue"}}}
local mirror = sphere(0.8):translate(1.2, 1.5, 0.8)
  :material{color={0.9, 0.9, 0.9}, diffuse=0.1, reflection=0.8, specular=0.6, shininess=80}
local glass = sphere(0.7):translate(-1.2, 0.8, 0.7)
  :material{color={1, 1, 1}, diffuse=0.05, transparency=0.9, ior=1.5, fresnel=true,
            specular=0.8, shininess=120}
return scene{
  objects = {room, mirror, glass},
  camera = camera{eye={-3.5, -4, 2.2}, look_at={0, 1, 0.8}, fov=70},
  lights = {point_light{pos={0, 0, 4.5}, intensity=0.9},
            point_light{pos={-4, -4, 4}, intensity=0.3}},
}
