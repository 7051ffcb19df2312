-- platonic.lua: the five Platonic solids of circumradius 1 on a row, each
-- standing on a face on a checkered floor. Every solid is a convex
-- polyhedron: the intersection of its face planes, traced exactly.
-- Render it with:  csgray render examples/platonic.lua -o out/platonic.png

local R = 1
local phi = (1 + math.sqrt(5)) / 2

-- Turns a solid so that its face with outward normal n faces down (-z):
-- a rotation about n × (-z) by the angle between n and -z.
local function faceDown(solid, n)
  local len = math.sqrt(n[1]^2 + n[2]^2 + n[3]^2)
  local angle = math.deg(math.acos(-n[3] / len))
  return solid:rotate{angle=angle, axis={-n[2], n[1], 0}}
end

-- The distance from the centre to a face (the inradius) over R: the height
-- at which each solid stands on the floor (see docs/script.md, Polyhedra).
local dual = math.sqrt((5 + 2 * math.sqrt(5)) / 15)

local solids = {
  -- A face already faces down: the tetrahedron's opposite its top vertex
  -- and the cube's.
  {tetrahedron{r=R}, R / 3, {0.85, 0.25, 0.2}},
  {hexahedron{r=R}, R / math.sqrt(3), {0.9, 0.65, 0.15}},
  -- The octahedron and the icosahedron have a face about the 3-fold axis
  -- (1, 1, 1); the dodecahedron a face with normal (0, φ, 1).
  {faceDown(octahedron{r=R}, {1, 1, 1}), R / math.sqrt(3), {0.3, 0.7, 0.3}},
  {faceDown(dodecahedron{r=R}, {0, phi, 1}), R * dual, {0.2, 0.5, 0.85}},
  {faceDown(icosahedron{r=R}, {1, 1, 1}), R * dual, {0.6, 0.3, 0.8}},
}

local objects = {}
for i, s in ipairs(solids) do
  local solid, height, colour = s[1], s[2], s[3]
  objects[i] = solid:translate((i - 3) * 2.4, 0, height)
    :material{color=colour, ambient=0.12, diffuse=0.8, specular=0.4, shininess=40}
end

objects[#objects + 1] = plane{normal={0, 0, 1}, offset=0}
  :material{color=checker{size=1, colors={{0.75, 0.75, 0.72}, {0.45, 0.45, 0.47}}},
            ambient=0.15, diffuse=0.85}

return scene{
  objects    = objects,
  camera     = camera{eye={0, -9, 2.8}, look_at={0, 0, 0.8}, fov=68},
  lights     = {point_light{pos={-6, -8, 10}, color={1, 0.96, 0.9}},
                point_light{pos={7, -10, 5}, color={0.3, 0.32, 0.4}}},
  background = {0.12, 0.13, 0.18},
}
