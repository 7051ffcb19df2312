// bench/parts/turned_vase.lua for POV-Ray 3.7: the same 200-point profile
// turned by a lathe, camera and lights. csgray's (x, y, z) is POV-Ray's
// <x, z, y> (see gear.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare N = 99;
#declare Height = 120;
#macro Radius(Z) (30 + 12 * sin(Z / 22) - 8 * cos(Z / 9) * (Z / Height)) #end

camera {
  location <0, 160, -260>
  look_at <0, 55, 0>
  right x * image_width / image_height
  angle 45
}
light_source { <150, 200, -100> color rgb 1 }
light_source { <-100, 150, -50> color rgb 0.5 }

lathe {
  linear_spline 2 * N + 3,
  <0, 0>,
  #for (K, 0, N - 1)
    #local Z = Height * K / (N - 1);
    <Radius(Z), Z>,
  #end
  #for (K, N - 1, 0, -1)
    #local Z = 3 + (Height - 3) * K / (N - 1);
    <Radius(Z) - 2, Z>,
  #end
  <0, 3>,
  <0, 0>
  pigment { color rgb <0.3, 0.5, 0.8> }
  finish { specular 0.5 roughness 1 / 40 }
}
