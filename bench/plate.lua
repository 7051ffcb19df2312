-- plate(N): the benchmark scene family of docs/performance.md.
-- A 100×100×10 plate; on its top face an N×N grid of spheres of radius
-- 0.32·p centred at height 10 (p = 100/N, centres at p/2 + i·p), joined by
-- union; an N×N grid of holes of radius 0.2·p on the same centres, from
-- z = -1 to z = 19, subtracted.   csgray render bench/plate.lua -D n=8 ...
local n = n or 8
-- The horizontal view angle; -D fov=29.6 is OpenSCAD's preview's at 800×600
-- (22.5° vertically), for bench/view/plate8.scad.
local fov = fov or 45
local p = 100 / n
local spheres, holes = {}, {}
for i = 0, n - 1 do
  for j = 0, n - 1 do
    local x, y = p / 2 + i * p, p / 2 + j * p
    spheres[#spheres + 1] = sphere{r=0.32 * p}:translate(x, y, 10)
    holes[#holes + 1] = cylinder{r=0.2 * p, h=20}:translate(x, y, -1)
  end
end
local plate = box{size={100, 100, 10}}
local part = difference(union(plate, union(spheres)), union(holes))
return scene{
  objects = {part:material{color={0.8, 0.6, 0.3}, specular=0.4, shininess=30}},
  camera = camera{eye={50, -90, 110}, look_at={50, 50, 0}, up={0, 0, 1}, fov=fov},
  lights = {point_light{pos={150, -100, 200}, intensity=1},
            point_light{pos={-50, -50, 150}, intensity=0.5}},
}
