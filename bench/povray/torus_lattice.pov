// bench/parts/torus_lattice.lua for POV-Ray 3.7: the same 400 tori, plane,
// camera and lights. csgray's (x, y, z) is POV-Ray's <x, z, y>.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <47.5, 45, -40>
  look_at <47.5, 0, 40>
  right x * image_width / image_height
  angle 60
}
light_source { <100, 150, -50> color rgb 1 }
light_source { <-50, 80, -20> color rgb 0.5 }
union {
  #for (I, 0, 19)
    #for (J, 0, 19)
      torus { 2, 0.5 translate <5 * I, 0.5, 5 * J> }
    #end
  #end
  pigment { color rgb <0.8, 0.5, 0.3> }
  finish { ambient 0.1 diffuse 0.9 specular 0.4 roughness 1 / 30 }
}
plane { y, 0 pigment { color rgb 0.9 } finish { ambient 0.1 diffuse 0.9 } }
background { color rgb <0.05, 0.05, 0.08> }
