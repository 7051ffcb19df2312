-- pipe_elbow.lua: a 60° pipe elbow with straight legs and bolted flanges,
-- written as in OpenSCAD: the solid elbow less a thinner one whose legs
-- reach past the ends. Each leg is a cylinder standing on an end face of
-- the bend (a rotate_extrude through 60°), and the export cuts it on the
-- bend's own polygon of that circle, so the leg and the bend meet point
-- for point at any angle (docs/cli.md, "Contacts").
--   csgray render examples/pipe_elbow.lua -o pipe_elbow.png
--   csgray export examples/pipe_elbow.lua -o pipe_elbow.stl
--   csgray check examples/pipe_elbow.lua

local angle = angle or 60      -- of the bend, in degrees
local R = bend_radius or 40    -- of the bend's centre line
local outer, bore = 9, 7       -- the pipe's radii
local leg = 25                 -- each straight leg's length
local flange, thick = 17, 4    -- the flanges' radius and thickness
local bolt, bolts = 1.7, 4     -- the bolt holes' radius, and how many

-- A rod bent through `angle` about the z axis, with a straight leg of
-- `length` on each end: the start face lies in the plane y = 0, the end
-- face turned by `angle` about z.
local function elbow(r, length)
  local bend = rotate_extrude{circle{r=r}:translate(R, 0), angle=angle}
  local first = cylinder{r=r, h=length}:rotate(90, 0, 0):translate(R, 0, 0)
  local second = cylinder{r=r, h=length}:rotate(-90, 0, 0):translate(R, 0, 0):rotate(0, 0, angle)
  return bend + first + second
end

-- A flange on the end of each leg, placed as that leg is, its bolt holes
-- on a circle between the pipe and the flange's rim.
local holes = {}
for i = 0, bolts - 1 do
  holes[#holes + 1] = cylinder{r=bolt, h=thick + 2}:translate((outer + flange) / 2, 0, -1)
      :rotate(0, 0, 45 + 360 * i / bolts)
end
local disc = difference(cylinder{r=flange, h=thick}, holes)
local first = disc:rotate(90, 0, 0):translate(R, -leg + thick, 0)
local second = disc:rotate(-90, 0, 0):translate(R, leg - thick, 0):rotate(0, 0, angle)

local pipe = (elbow(outer, leg) + first + second) - elbow(bore, leg + 1)

return scene{
  objects = {pipe:material{color={0.72, 0.45, 0.2}, specular=0.5, shininess=60}},
  camera = camera{eye={130, -110, 120}, look_at={22, 10, 0}, fov=40},
  lights = {point_light{pos={120, -150, 160}}, point_light{pos={-80, -60, 90}, intensity=0.5}},
}
