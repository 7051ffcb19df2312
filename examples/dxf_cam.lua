-- dxf_cam.lua: a cam plate from a DXF drawing whose outline is a SPLINE
-- (a closed cubic B-spline, as CAD programs draw free curves; OpenSCAD
-- skips such entities). The spline stays an exact curve: csgray reads it
-- as the cubic Bézier pieces it is made of, so the cam's face is smooth
-- in the render and within the tolerance in the export. The layer "bore"
-- is a circle written as drawing programs write circles as splines (a
-- rational quadratic of four quarter arcs), which csgray reads as the
-- exact circle it is; "key" is a keyway; both are cut through.
--   csgray render examples/dxf_cam.lua -o cam.png
--   csgray export examples/dxf_cam.lua -o cam.stl
local drawing = "drawings/cam.dxf"
local cam = import_dxf{file=drawing, layer="cam"}
local bore = import_dxf{file=drawing, layer="bore"} + import_dxf{file=drawing, layer="key"}
local plate = linear_extrude{cam - bore, height=thickness or 8}
-- A hub around the bore on one side.
local hub = linear_extrude{circle{r=11} - bore, height=14}
return scene{
  objects = {(plate + hub):material{color={0.75, 0.72, 0.68}, specular=0.5, shininess=60}},
  camera = camera{eye={-30, -60, 90}, look_at={6, 0, 4}, up={0, 0, 1}, fov=40},
  lights = {point_light{pos={-60, -80, 120}, intensity=1}, point_light{pos={80, -20, 60}, intensity=0.4}},
}
