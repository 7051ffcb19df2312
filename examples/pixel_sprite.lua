-- pixel_sprite.lua: a coaster with a pixel-art sprite raised on it, each
-- pixel a box of its own, all as high as each other, as OpenSCAD scripts
-- draw QR codes and pixel art. Pixels that meet only at a corner (the
-- sprite's feet and antennae) touch along an edge: the export joins them
-- there by a bridge a tenth of the tolerance wide, as a union joins solids
-- that share only an edge, and makes all pixels one extrusion of their
-- outline (docs/cli.md, "Contacts").
--   csgray render examples/pixel_sprite.lua -o pixel_sprite.png
--   csgray export examples/pixel_sprite.lua -o pixel_sprite.stl

local sprite = {
  "..#.....#..",
  "...#...#...",
  "..#######..",
  ".##.###.##.",
  "###########",
  "#.#######.#",
  "#.#.....#.#",
  "...##.##...",
}
local p = pixel or 4     -- [2:8] pixel size, mm
local raised = raise or 1.5 -- [0.5:4] pixel height above the plate, mm
local border = 2 * p

local W, H = #sprite[1] * p + 2 * border, #sprite * p + 2 * border
local plate = box{size={W, H, 3}}:translate(0, 0, -3)
local pixels = {}
for row, line in ipairs(sprite) do
  for col = 1, #line do
    if line:sub(col, col) == "#" then
      pixels[#pixels + 1] = box{size={p, p, raised}}:translate(border + (col - 1) * p,
                                                                H - border - row * p, 0)
    end
  end
end
local coaster = plate:material{color={0.9, 0.88, 0.8}}
               + union(pixels):material{color={0.2, 0.6, 0.3}, specular=0.3, shininess=30}

return scene{
  objects = {coaster},
  camera = camera{eye={W / 2 + 0.25 * W, -0.8 * H, 0.9 * H}, look_at={W / 2, H / 2, 0}, fov=45},
  lights = {point_light{pos={W, -H, 2 * H}, intensity=1},
            point_light{pos={-W, H, H}, intensity=0.4}},
}
