-- pythagoras_tree.lua: a Pythagoras tree of cubes. Each cube carries two
-- smaller ones tilted by `angle` and 90° − angle, in a plane that turns a
-- quarter turn at each level, so the tree branches in space. Each cube
-- stands on its parent's top face, tilted: at other angles and levels the
-- export may fail where a tilted face meets its parent's at a hair's
-- breadth (the message names the place); this one exports.
--   csgray render examples/pythagoras_tree.lua -o tree.png
local level = level or 3
local angle = angle or 45
local tree = pythagoras_tree_3d{level = level, size = 10, angle = angle}
return tree:material{color = "sienna", specular = 0.2}
