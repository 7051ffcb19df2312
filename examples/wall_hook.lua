-- wall_hook.lua: a hook for the wall, drawn as a 2D profile and extruded.
-- The profile is a back plate, a half ring and a tip; offsets round it:
-- growing and then shrinking by r fills the inner corners with arcs of
-- radius r, shrinking and then growing rounds the outer ones. The arcs
-- are exact, and so is the extruded solid. Two countersunk screw holes go
-- through the plate.   csgray render examples/wall_hook.lua -o hook.png
local width  = width or 12     -- how thick the printed hook is
local fillet = fillet or 2     -- radius of the inner corners
local round  = round or 1      -- radius of the outer corners

local plate = rectangle{size={6, 60}}
local ring = (circle{r=14} - circle{r=8}):translate(20, 14)
local cup = ring * rectangle{size={40, 14}}  -- the lower half of the ring
local tip = rectangle{size={6, 10}}:translate(28, 14)
local profile = (plate + cup + tip)
  :offset{r=fillet}:offset{r=-fillet}
  :offset{r=-round}:offset{r=round}

local hook = linear_extrude{profile, height=width}
-- A screw hole along x through the plate, widening to the front (x = 6).
local function screw(y)
  local shank = cylinder{d=4, h=20, center=true}:rotate(0, 90, 0)
  local countersink = cylinder{d1=4, d2=9, h=2.5}:rotate(0, 90, 0):translate(3.5, 0, 0)
  return (shank + countersink):translate(0, y, width / 2)
end
return (hook - screw(32) - screw(52)):material{color={0.3, 0.6, 0.4}, specular=0.3, shininess=20}
