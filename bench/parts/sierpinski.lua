-- The Sierpinski tetrahedron of level 6 (4 096 tetrahedra, a union made
-- by the script library's recursion) over a plane, two point lights with
-- shadows: the render benchmark of fractal compounds against POV-Ray
-- (bench/povray/sierpinski.pov is the same scene, its tetrahedra as
-- intersections of four planes).
local fractal = sierpinski_tetrahedron{level = level or 6, size = 100}
return scene{
  objects = {fractal:material{color = {0.85, 0.7, 0.3}, specular = 0.4, shininess = 30},
             plane{}:translate(0, 0, -50 / 3):material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {110, -140, 90}, look_at = {0, 0, 2}, up = {0, 0, 1}, fov = 40},
  lights = {point_light{pos = {100, -150, 200}, intensity = 1},
            point_light{pos = {-150, -50, 100}, intensity = 0.5}},
}
