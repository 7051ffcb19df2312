-- A 60-tooth involute gear (module 2, pressure angle 20°, 20 points a
-- tooth: 1 200 in all), 20 thick, extruded with a twist (default 30°), minus
-- a keyed bore of radius 10. The benchmark of sweeps in docs/performance.md;
-- bench/povray/gear.pov and bench/manifold/parts.mjs build the same gear.
--   csgray render bench/parts/gear.lua -D twist=0 ...
local teeth, module, twist = 60, 2, twist or 30
local pitch = module * teeth / 2
local base = pitch * math.cos(math.rad(20))
local tip, root = pitch + module, pitch - 1.25 * module
-- The involute's polar angle at radius r: tan α − α, cos α = base / r
-- (any gear text, e.g. Dudley's Handbook of Practical Gear Design, ch. 1).
local function involute(r)
  local a = math.sqrt(math.max(0, (r / base) ^ 2 - 1))
  return a - math.atan(a)
end
local half = math.pi / (2 * teeth) + involute(pitch)  -- half a tooth's angle, less the involute
local flank = 9  -- points up each flank, from the root circle to the tip
local points = {}
local function add(r, angle) points[#points + 1] = {r * math.cos(angle), r * math.sin(angle)} end
for i = 0, teeth - 1 do
  local c = 2 * math.pi * i / teeth
  for k = 0, flank - 1 do
    local r = root + (tip - root) * k / (flank - 1)
    add(r, c - (half - involute(math.max(r, base))))
  end
  for k = flank - 1, 0, -1 do
    local r = root + (tip - root) * k / (flank - 1)
    add(r, c + (half - involute(math.max(r, base))))
  end
  local gap = 2 * math.pi / teeth  -- two points along the root between teeth
  local from, to = c + half - involute(math.max(root, base)), c + gap - half + involute(math.max(root, base))
  add(root, from + (to - from) / 3)
  add(root, from + 2 * (to - from) / 3)
end
local gear = linear_extrude{polygon{points=points}, height=20, twist=twist}
local bore = cylinder{r=10, h=22}:translate(0, 0, -1) + box{size={6, 4, 22}}:translate(7, -2, -1)
return scene{
  objects = {(gear - bore):material{color={0.75, 0.75, 0.8}, specular=0.5, shininess=40}},
  camera = camera{eye={0, -150, 120}, look_at={0, 0, 5}, up={0, 0, 1}, fov=45},
  lights = {point_light{pos={150, -100, 200}, intensity=1},
            point_light{pos={-100, -50, 150}, intensity=0.5}},
}
