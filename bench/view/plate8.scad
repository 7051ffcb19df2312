// plate(8) of bench/plate.lua for OpenSCAD's preview: a 100×100×10 plate,
// an 8×8 grid of spheres of radius 0.32·p at height 10 (p = 12.5), an 8×8
// grid of holes of radius 0.2·p from z = -1 to z = 19, subtracted; the
// camera of plate.lua (eye, centre). $fn = 48 keeps the spheres' facets
// about as fine as a preview at this size shows.
n = 8;
p = 100 / n;
$fn = 48;
color([0.8, 0.6, 0.3])
difference() {
  union() {
    cube([100, 100, 10]);
    for (i = [0 : n - 1], j = [0 : n - 1])
      translate([p / 2 + i * p, p / 2 + j * p, 10]) sphere(r = 0.32 * p);
  }
  for (i = [0 : n - 1], j = [0 : n - 1])
    translate([p / 2 + i * p, p / 2 + j * p, -1]) cylinder(r = 0.2 * p, h = 20);
}
