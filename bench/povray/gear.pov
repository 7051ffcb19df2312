// bench/parts/gear.lua with twist=0 for POV-Ray 3.7, which has no twisted
// prism: the same 1 200 points, bore, camera and lights. csgray's (x, y, z)
// is POV-Ray's <x, z, y> (z up there, y up here; the swap of two axes also
// turns csgray's right-handed frame into POV-Ray's left-handed one, so the
// images are not mirrored).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Teeth = 60;
#declare Module = 2;
#declare Pitch = Module * Teeth / 2;
#declare Base = Pitch * cos(radians(20));
#declare Tip = Pitch + Module;
#declare Root = Pitch - 1.25 * Module;
#macro Involute(R)
  #local A = sqrt(max(0, (R / Base) * (R / Base) - 1));
  (A - atan2(A, 1))
#end
#declare Half = pi / (2 * Teeth) + Involute(Pitch);
#declare Flank = 9;
#macro Point(R, Angle) <R * cos(Angle), R * sin(Angle)> #end

camera {
  location <0, 120, -150>
  look_at <0, 5, 0>
  right x * image_width / image_height
  angle 45
}
light_source { <150, 200, -100> color rgb 1 }
light_source { <-100, 150, -50> color rgb 0.5 }

difference {
  prism {
    linear_sweep linear_spline 0, 20, Teeth * 20 + 1,
    #for (I, 0, Teeth - 1)
      #local C = 2 * pi * I / Teeth;
      #for (K, 0, Flank - 1)
        #local R = Root + (Tip - Root) * K / (Flank - 1);
        Point(R, C - (Half - Involute(max(R, Base)))),
      #end
      #for (K, Flank - 1, 0, -1)
        #local R = Root + (Tip - Root) * K / (Flank - 1);
        Point(R, C + (Half - Involute(max(R, Base)))),
      #end
      #local From = C + Half - Involute(max(Root, Base));
      #local To = C + 2 * pi / Teeth - Half + Involute(max(Root, Base));
      Point(Root, From + (To - From) / 3),
      Point(Root, From + 2 * (To - From) / 3),
    #end
    Point(Root, -(Half - Involute(max(Root, Base))))
  }
  cylinder { <0, -1, 0>, <0, 21, 0>, 10 }
  box { <7, -1, -2>, <13, 21, 2> }
  pigment { color rgb <0.75, 0.75, 0.8> }
  finish { specular 0.5 roughness 1 / 40 }
}
