-- polyhedron.lua: a brilliant-cut gem built from points and faces (OpenSCAD's
-- polyhedron), its girdle rounded by a sphere, over a checkerboard floor.
--
-- Points are numbered from 0 in the faces, and every face is listed
-- clockwise as seen from outside the gem.

local table_r, table_z = 0.5, 0.45 -- the flat top: an octagon
local girdle_r = 1.0                -- the widest ring: 16 points at z = 0
local culet_z = -0.95               -- the point at the bottom

local points = {}
for i = 0, 7 do -- the table: points 0 to 7
  local a = math.rad(45 * i)
  points[#points + 1] = {table_r * math.cos(a), table_r * math.sin(a), table_z}
end
for k = 0, 15 do -- the girdle: points 8 to 23
  local a = math.rad(22.5 * k)
  points[#points + 1] = {girdle_r * math.cos(a), girdle_r * math.sin(a), 0}
end
points[#points + 1] = {0, 0, culet_z} -- the culet: point 24

local function t(i) return i % 8 end
local function g(k) return 8 + k % 16 end
local culet = 24

-- The table faces up: seen from above, clockwise is decreasing angle.
local faces = {{7, 6, 5, 4, 3, 2, 1, 0}}
for i = 0, 7 do
  faces[#faces + 1] = {t(i), t(i + 1), g(2 * i + 1)}     -- a star facet
  faces[#faces + 1] = {t(i), g(2 * i + 1), g(2 * i)}     -- two upper girdle facets
  faces[#faces + 1] = {t(i + 1), g(2 * i + 2), g(2 * i + 1)}
end
for k = 0, 15 do
  faces[#faces + 1] = {g(k), g(k + 1), culet}            -- the pavilion
end

local gem = (polyhedron{points=points, faces=faces} * sphere{r=0.94})
  :scale(1.3)
  :rotate(0, 14, 20)
  :translate(0, 0, 1.45)
  :material{color={0.8, 0.1, 0.3}, ambient=0.05, diffuse=0.35, specular=0.9, shininess=150,
            transparency=0.75, filter={0.95, 0.35, 0.5}, ior=1.76, fresnel=true}

local floor = plane{normal={0, 0, 1}}
  :material{color=checker{size=1, colors={{0.85, 0.85, 0.8}, {0.2, 0.22, 0.3}}}}

return scene{
  objects = {floor, gem},
  camera = camera{eye={1.2, -5.2, 4.6}, look_at={0, 0, 1.1}, fov=45},
  lights = {point_light{pos={-4, -5, 9}, intensity=0.9},
            point_light{pos={5, -3, 4}, intensity=0.4}},
  background = {0.55, 0.65, 0.8},
}
