-- pythagoras_tree.lua: a Pythagoras tree of cubes. Each cube carries two
-- smaller ones tilted by `angle` and 90° − angle, in a plane that turns a
-- quarter turn at each level, so the tree branches in space. Each cube
-- sinks a hundredth of its side into its parent; at deeper levels
-- branches meet each other at a hair's breadth, where an export may fail
-- (the message names the place). Rendering takes any level.
--   csgray render examples/pythagoras_tree.lua -o tree.png
local level = level or 2
local angle = angle or 45
local tree = pythagoras_tree_3d{level = level, size = 10, angle = angle}
return tree:material{color = "sienna", specular = 0.2}
