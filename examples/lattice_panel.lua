-- lattice_panel.lua: a vent grille, a frame with bars at ±45° across its
-- opening, each bar a box as thick as the frame, clipped to the frame's
-- outline (by a box that sticks out above and below), and a screw hole
-- in each corner. Every bar's top and bottom lie in the frame's planes;
-- the export makes the frame and the bars one extrusion of the boolean
-- of their outlines, which is the same solid (docs/cli.md, "Contacts").
--   csgray render examples/lattice_panel.lua -o lattice_panel.png
--   csgray export examples/lattice_panel.lua -o lattice_panel.stl

local W = width or 80     -- [40:160] panel width, mm
local H = height or 60    -- [40:160] panel height, mm
local t = thickness or 3  -- [1.5:6] panel thickness, mm
local pitch = pitch or 8  -- [5:16] distance between bars, mm
local rim = 6             -- frame width, mm

local frame = box{size={W, H, t}} - box{size={W - 2 * rim, H - 2 * rim, t + 2}}:translate(rim, rim, -1)
local long = 1.5 * (W + H)  -- a bar at 45° through any point of the panel spans it
local bars = {}
for i = -math.ceil((W + H) / 2 / pitch), math.ceil((W + H) / 2 / pitch) do
  for _, angle in ipairs({45, -45}) do
    bars[#bars + 1] = box{size={1.6, long, t}}:translate(-0.8, -long / 2, 0)
                        :rotate(0, 0, angle):translate(W / 2 + i * pitch, H / 2, 0)
  end
end
local panel = frame + union(bars) * box{size={W, H, t + 2}}:translate(0, 0, -1)

local holes = {}
for _, corner in ipairs({{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}) do
  holes[#holes + 1] = cylinder{d=3.4, h=t + 2}:translate(W / 2 + corner[1] * (W / 2 - rim / 2),
                                                        H / 2 + corner[2] * (H / 2 - rim / 2), -1)
end

return scene{
  objects = {(panel - union(holes)):material{color={0.25, 0.45, 0.7}, specular=0.4, shininess=40}},
  camera = camera{eye={W / 2 + 0.25 * W, -1.1 * H, 1.5 * H}, look_at={W / 2, H / 2, 0}, fov=45},
  lights = {point_light{pos={W, -H, 2 * H}, intensity=1},
            point_light{pos={-W, H, H}, intensity=0.4}},
}
