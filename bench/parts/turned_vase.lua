-- A vase turned from a profile of 200 points: from the axis, an outer wall
-- of 99 points up a wavy silhouette, an inner wall 2 in from it of 99
-- points back down to a floor 3 thick, and back to the axis. The
-- benchmark of revolutions in docs/performance.md;
-- bench/povray/turned_vase.pov and bench/manifold/parts.mjs build the same.
local n, height = 99, 120
local function radius(z) return 30 + 12 * math.sin(z / 22) - 8 * math.cos(z / 9) * (z / height) end
local points = {{0, 0}}
for k = 0, n - 1 do
  local z = height * k / (n - 1)
  points[#points + 1] = {radius(z), z}
end
for k = n - 1, 0, -1 do
  local z = 3 + (height - 3) * k / (n - 1)
  points[#points + 1] = {radius(z) - 2, z}
end
points[#points + 1] = {0, 3}
local vase = rotate_extrude{polygon{points=points}}
return scene{
  objects = {vase:material{color={0.3, 0.5, 0.8}, specular=0.5, shininess=40}},
  camera = camera{eye={0, -260, 160}, look_at={0, 0, 55}, up={0, 0, 1}, fov=45},
  lights = {point_light{pos={150, -100, 200}, intensity=1},
            point_light{pos={-100, -50, 150}, intensity=0.5}},
}
