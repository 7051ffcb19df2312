-- twisted_gear.lua: an involute spur gear extruded with a twist (a
-- herringbone's half), with a keyed bore. The teeth are a polygon of the
-- involute's points; the twist turns the profile as it rises, and the
-- sides a ray meets are the exact helicoidal sweep of each edge.
--   csgray render examples/twisted_gear.lua -o gear.png -D teeth=30 -D twist=25
local teeth  = teeth or 24
local module = module or 2     -- pitch diameter / teeth, mm
local twist  = twist or 20     -- degrees over the height
local height = height or 12
assert(teeth >= 8 and teeth <= 200, "teeth must be between 8 and 200")

local pitch = module * teeth / 2
local base = pitch * math.cos(math.rad(20))   -- pressure angle 20°
local tip, root = pitch + module, pitch - 1.25 * module
-- The involute's polar angle at radius r: tan α − α with cos α = base / r
-- (e.g. Dudley, Handbook of Practical Gear Design, ch. 1).
local function involute(r)
  local a = math.sqrt(math.max(0, (r / base) ^ 2 - 1))
  return a - math.atan(a)
end
local half = math.pi / (2 * teeth) + involute(pitch)
local points = {}
local function add(r, angle) points[#points + 1] = {r * math.cos(angle), r * math.sin(angle)} end
for i = 0, teeth - 1 do
  local c = 2 * math.pi * i / teeth
  for k = 0, 6 do
    local r = root + (tip - root) * k / 6
    add(r, c - (half - involute(math.max(r, base))))
  end
  for k = 6, 0, -1 do
    local r = root + (tip - root) * k / 6
    add(r, c + (half - involute(math.max(r, base))))
  end
end

local gear = linear_extrude{polygon{points=points}, height=height, twist=twist}
-- The bore and its keyway stay straight: they are cut after the twist.
local bore = cylinder{d=8, h=height + 2}:translate(0, 0, -1)
local key = box{size={3, 3, height + 2}}:translate(3, -1.5, -1)
return (gear - bore - key):material{color={0.75, 0.75, 0.8}, specular=0.5, shininess=40}
