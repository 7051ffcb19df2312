-- Focal blur: a row of turned pawns seen through a lens 0.6 wide, in
-- focus on the third (POV-Ray's aperture, focal_point and blur_samples).
-- The pawns before and behind it blur by the circle of confusion, which
-- grows with their distance from the plane in focus; the third stays as
-- sharp as a pinhole would show it. Each pixel takes 36 rays through the
-- lens; --samples above that spends more where the picture has edges.
local function pawn()
  local base = cylinder{r1=1.0, r2=0.8, h=0.3}
  local body = cylinder{r1=0.7, r2=0.25, h=1.6}:translate(0, 0, 0.3)
  local collar = torus{R=0.35, r=0.1}:translate(0, 0, 1.8)
  local head = sphere{r=0.5}:translate(0, 0, 2.25)
  return base + body + collar + head
end

local pawns = {}
for i = 0, 5 do
  local color = i % 2 == 0 and {0.85, 0.8, 0.7} or {0.25, 0.12, 0.08}
  pawns[#pawns + 1] = pawn():translate(i * 1.2 - 3, i * 3, 0)
    :material{color=color, specular=0.5, shininess=60, reflection=0.05}
end

local board = plane{}:material{color=checker{size=1.5, colors={{0.8, 0.8, 0.75}, {0.15, 0.15, 0.15}}}}

return scene{
  objects = {board, union(pawns)},
  camera = camera{eye={-7, -2, 2.2}, look_at={1, 6, 0.8}, fov=40,
                  aperture=0.6, focal_point={-0.6, 6, 1.2}, blur_samples=36},
  lights = {point_light{pos={-8, -4, 12}, intensity=0.9},
            point_light{pos={10, 2, 8}, intensity=0.3}},
  background = {0.6, 0.7, 0.85},
}
