-- mesh_import.lua: a part read from a mesh file, drilled and shown.
--   csgray render examples/mesh_import.lua -o mesh_import.png
-- mesh{file=...} reads STL, OBJ, OFF, PLY or 3MF; the path is relative to this
-- script and may not leave its folder (unless allowed with --allow-path).
-- The mesh is a solid like any other: here two holes are cut through it.
-- A file that is not a closed solid is refused, saying where it is open,
-- non-manifold or self-intersecting; repair=true makes the repairs that
-- can be made (stitching, orientation, degenerate faces) and reports them.

-- An angle of 30 x 30 mm legs, 5 mm thick and 20 mm deep (y from 0 to 20).
local angle = mesh{file="meshes/bracket.stl"}

local hole = cylinder{d=6, h=20, center=true}
local drilled = angle
  - hole:translate(18, 10, 2.5)                    -- through the flat leg
  - hole:rotate(0, 90, 0):translate(2.5, 10, 18)   -- through the upright leg

return scene{
  objects = {drilled:material{color={0.7, 0.5, 0.3}, specular=0.4}},
  camera  = camera{eye={80, -60, 60}, look_at={12, 10, 10}, fov=35},
  lights  = {point_light{pos={60, -80, 100}},
             point_light{pos={-40, 40, 60}, intensity=0.4}},
  background = {0.9, 0.9, 0.92},
}
