// bench/parts/sierpinski.lua for POV-Ray 3.7: the Sierpinski tetrahedron
// of level 6, its 4 096 tetrahedra as one mesh of their faces (as
// intersections of planes POV-Ray finds no bounds for them and tests every
// one on every ray: 8 minutes at 512x384), plane, camera and lights.
// csgray's (x, y, z) is POV-Ray's <x, z, y>. A tetrahedron of
// circumradius R has corners at R·c for the unit vectors c below.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <110, 90, -140>
  look_at <0, 2, 0>
  right x * image_width / image_height
  angle 40
}
light_source { <100, 200, -150> color rgb 1 }
light_source { <-150, 100, -50> color rgb 0.5 }
#declare S = 2 * sqrt(2) / 3;
#declare C = array[4] {
  <0, 1, 0>,
  <S, -1 / 3, 0>,
  <S * cos(2 * pi / 3), -1 / 3, S * sin(2 * pi / 3)>,
  <S * cos(4 * pi / 3), -1 / 3, S * sin(4 * pi / 3)>
}
#macro Tetrahedron(P, R)
  triangle { P + R * C[0], P + R * C[1], P + R * C[2] }
  triangle { P + R * C[0], P + R * C[2], P + R * C[3] }
  triangle { P + R * C[0], P + R * C[3], P + R * C[1] }
  triangle { P + R * C[1], P + R * C[2], P + R * C[3] }
#end
#macro Place(P, R, Depth)
  #if (Depth = 0)
    Tetrahedron(P, R)
  #else
    #for (K, 0, 3)
      Place(P + C[K] * R / 2, R / 2, Depth - 1)
    #end
  #end
#end
mesh {
  Place(<0, 0, 0>, 50, 6)
  pigment { color rgb <0.85, 0.7, 0.3> }
  finish { ambient 0.1 diffuse 0.9 specular 0.4 roughness 1 / 30 }
}
plane { y, -50 / 3 pigment { color rgb 0.9 } finish { ambient 0.1 diffuse 0.9 } }
background { color rgb <0.05, 0.05, 0.08> }
