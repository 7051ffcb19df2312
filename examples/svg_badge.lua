-- svg_badge.lua: a badge from an SVG drawing. The drawing's group "plate"
-- is a 60 × 40 mm plate with rounded corners and a hole to hang it by (a
-- hole by the even-odd rule); its group "emblem" a heart of arcs and cubic
-- Bézier curves, a star, three dots (<use> of one circle) and a bar with
-- round ends, raised on the plate. The curves stay exact: the heart's
-- sides are Bézier curves in the render, and arcs are arcs.
--   csgray render examples/svg_badge.lua -o badge.png
--   csgray export examples/svg_badge.lua -o badge.stl
local drawing = "drawings/badge.svg"
local plate = import_svg{file=drawing, id="plate"}
local emblem = import_svg{file=drawing, id="emblem"}
local thickness = thickness or 3
local base = linear_extrude{plate, height=thickness}:material{color={0.75, 0.75, 0.78}}
local raised = linear_extrude{emblem, height=1.5}:translate(0, 0, thickness)
return base + raised:material{color={0.65, 0.05, 0.05}}
