// bench/parts/glass.lua for POV-Ray 3.7: the same glass lens, glass box
// less a ball, mirror ball, checkerboard, camera and lights, traced to
// depth 8. csgray's (x, y, z) is POV-Ray's <x, z, y>; its turn by 90°
// about x is POV-Ray's by -90°.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera {
  location <0, 12, -22>
  look_at <0, 2, 2>
  right x * image_width / image_height
  angle 50
}
light_source { <20, 40, -20> color rgb 1 }
light_source { <-30, 20, -10> color rgb 0.5 }
#declare Glass = material {
  texture { pigment { color rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.05 } }
  interior { ior 1.5 }
}
intersection {
  sphere { <0, -3, 0>, 4 }
  sphere { <0, 3, 0>, 4 }
  rotate -90 * x
  translate <-4, 3, 0>
  material { Glass }
}
difference {
  box { -2.5, 2.5 }
  sphere { <0, 2, 0>, 3 }
  translate <4, 2.5, 1>
  material { Glass }
}
sphere {
  <1, 3, 9>, 3
  pigment { color rgb 0.9 }
  finish { ambient 0 diffuse 0.1 reflection 0.9 }
}
plane {
  y, 0
  pigment { checker color rgb 0.9 color rgb <0.2, 0.2, 0.25> scale 2 }
  finish { ambient 0.1 diffuse 0.9 }
}
background { color rgb <0.05, 0.05, 0.08> }
