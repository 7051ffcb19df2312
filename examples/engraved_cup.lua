-- engraved_cup.lua: a pen cup with a name engraved around it, letter by
-- letter (docs/script.md, "Text"). Each letter is cut from the plane that
-- touches the cup along one line, as OpenSCAD's
-- translate([0, 0, R - d]) linear_extrude(d) writes an engraving: the
-- export moves that face clear of the cup's mesh, so no skin of the wall
-- is left over the letters.
--   csgray render examples/engraved_cup.lua -o engraved_cup.png
--   csgray export examples/engraved_cup.lua -o engraved_cup.stl
--   csgray check examples/engraved_cup.lua

local R, H, wall = radius or 30, height or 70, 3
local word, depth = name or "CSGRAY", 1
local font = "DejaVu Sans:style=Bold"
local size = 10

local cup = cylinder{r=R, h=H} - cylinder{r=R - wall, h=H}:translate(0, 0, wall)

-- A letter stands in the plane y = -R, which touches the cup at its front,
-- reaches `depth` into the wall, and is turned about the cup's axis to
-- its place in the word.
local step = math.deg(0.85 * size / R)
local letters = {}
for i = 1, #word do
  local letter = text{word:sub(i, i), size=size, font=font, halign="center", valign="center"}
  letters[#letters + 1] = linear_extrude{letter, height=depth}
      :rotate(90, 0, 0):translate(0, -R + depth, H / 2):rotate(0, 0, (i - (#word + 1) / 2) * step)
end

return scene{
  objects = {difference(cup, letters):material{color={0.2, 0.35, 0.6}, specular=0.4, shininess=40}},
  camera = camera{eye={0, -190, 110}, look_at={0, 0, 30}, fov=40},
  lights = {point_light{pos={80, -120, 140}}, point_light{pos={-90, -40, 60}, intensity=0.5}},
}
