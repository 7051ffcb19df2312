// bench/parts/superellipsoids.lua for POV-Ray 3.7: the same 64
// superellipsoids, plane, camera and lights. csgray's (x, y, z) is
// POV-Ray's <x, z, y>; the shape is symmetric under that swap of axes
// except for which exponent shapes which direction, so each is turned to
// put POV-Ray's z axis (the one n shapes) on its y, csgray's up.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <8.75, 16, -14>
  look_at <8.75, 0, 8.75>
  right x * image_width / image_height
  angle 60
}
light_source { <40, 60, -20> color rgb 1 }
light_source { <-20, 30, -10> color rgb 0.5 }
union {
  #for (I, 0, 7)
    #for (J, 0, 7)
      superellipsoid { <0.1 + 1.9 * I / 7, 0.1 + 1.9 * J / 7>
        rotate 90 * x translate <2.5 * I, 1, 2.5 * J> }
    #end
  #end
  pigment { color rgb <0.3, 0.5, 0.8> }
  finish { ambient 0.1 diffuse 0.9 specular 0.4 roughness 1 / 30 }
}
plane { y, 0 pigment { color rgb 0.9 } finish { ambient 0.1 diffuse 0.9 } }
background { color rgb <0.05, 0.05, 0.08> }
