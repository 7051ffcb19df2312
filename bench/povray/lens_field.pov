// bench/parts/lens_field.lua for POV-Ray 3.7: the same 200 lens parts,
// turned by the same Lehmer sequence, plane, camera and lights.
// csgray's (x, y, z) is POV-Ray's <x, z, y>; swapping two axes mirrors,
// so csgray's turn by a about x (or z) is POV-Ray's by -a about x (or y).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <57, 60, -40>
  look_at <57, 0, 27>
  right x * image_width / image_height
  angle 60
}
light_source { <120, 150, -50> color rgb 1 }
light_source { <-50, 80, -20> color rgb 0.5 }
#declare Seed = 12345;
#macro Random()
  #declare Seed = mod(Seed * 16807, 2147483647);
  (Seed / 2147483647)
#end
#declare Lens = difference {
  intersection {
    sphere { <0, -2, 0>, 3 }
    sphere { <0, 2, 0>, 3 }
    cylinder { <0, -2, 0>, <0, 2, 0>, 2 }
  }
  sphere { 0, 1 scale <0.8, 1.5, 0.8> }
}
union {
  #for (I, 0, 19)
    #for (J, 0, 9)
      #local AX = 360 * Random();
      #local AZ = 360 * Random();
      object { Lens rotate -AX * x rotate -AZ * y translate <6 * I, 2.5, 6 * J> }
    #end
  #end
  pigment { color rgb <0.3, 0.5, 0.8> }
  finish { ambient 0.1 diffuse 0.9 specular 0.4 roughness 1 / 30 }
}
plane { y, 0 pigment { color rgb 0.9 } finish { ambient 0.1 diffuse 0.9 } }
background { color rgb <0.05, 0.05, 0.08> }
