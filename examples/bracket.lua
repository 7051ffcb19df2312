-- bracket.lua: an angle bracket with parameters that the command line can
-- set, e.g.  csgray render examples/bracket.lua -o bracket.png -D holes=3
-- Shows rotate, mirror, the n-ary booleans, and material on a whole part.

local holes     = holes or 2          -- holes per leg
local length    = length or 60        -- leg length, mm
local width     = width or 30
local thickness = thickness or 5
local hole_d    = hole_d or 6

assert(holes >= 1 and holes <= 10, "holes must be between 1 and 10")

-- One leg lying flat, with its row of holes.
local function leg()
  local cuts = {}
  for i = 1, holes do
    local x = length * i / (holes + 1)
    cuts[i] = cylinder{d=hole_d, h=3 * thickness, center=true}:translate(x, width / 2, thickness / 2)
  end
  return difference(box{size={length, width, thickness}}, union(cuts))
end

-- The second leg stands up: rotate the flat leg by -90° about Y.
local base = leg()
local wall = leg():rotate(0, -90, 0):translate(thickness, 0, 0)

-- A triangular gusset on each side: a box cut diagonally by a half-space.
local gusset = (box{size={length / 2, thickness, length / 2}}
                * half_space{normal={1, 0, 1}, offset=length / 2}):translate(thickness, 0, thickness)
local gussets = union(gusset, gusset:mirror(0, 1, 0):translate(0, width, 0))

local bracket = union(base, wall, gussets):material{color={0.55, 0.6, 0.7}}
return scene{
  objects = {bracket},
  camera  = camera{eye={170, -150, 140}, look_at={30, 15, 24}, fov=35},
  lights  = {point_light{pos={120, -100, 150}},
             point_light{pos={-60, 80, 90}, intensity=0.4}},
  background = {0.9, 0.9, 0.92},
}
