-- mesh_3mf.lua: a part read from a 3MF file, the format slicers and CAD
-- programs exchange (and csgray export writes). mesh{} takes the build of
-- the file: each object placed by its build item's transform.
--   csgray render examples/mesh_3mf.lua -o mesh_3mf.png
-- meshes/bracket.3mf is examples/meshes/bracket.stl written as 3MF: the
-- same angle of 30 x 30 mm legs; here a mirrored copy is set behind it,
-- leg to leg, to make a tee.
local angle = mesh{file="meshes/bracket.3mf"}
local lo, hi = angle:bounds()
assert(hi[1] - lo[1] == 30 and hi[3] - lo[3] == 30, "the bracket's legs are 30 mm")
return angle + angle:mirror(1, 0, 0)
