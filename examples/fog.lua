-- Fog: a colonnade that fades into the mist (POV-Ray's fog of constant
-- density). Over a way of length d a ray keeps exp(-d / 25) of what it
-- sees and takes the rest from the fog's colour: at 25 units a column
-- shows 37 % of itself, at 75 units 5 %, and the sky is the fog alone.
-- Fog lies in the air, not inside glass; shadow rays pass through it.
local column = cylinder{r=0.6, h=6} + box{size={1.8, 1.8, 0.4}}:translate(-0.9, -0.9, 6)
  + box{size={1.6, 1.6, 0.3}}:translate(-0.8, -0.8, 0)

local columns = {}
for i = 0, 11 do
  for _, x in ipairs({-4, 4}) do
    columns[#columns + 1] = column:translate(x, i * 6, 0)
  end
end
local stone = {color={0.75, 0.7, 0.62}, specular=0.2}

return scene{
  objects = {
    plane{}:material{color=checker{size=2, colors={{0.55, 0.5, 0.45}, {0.35, 0.32, 0.3}}}},
    union(columns):material(stone),
  },
  camera = camera{eye={0, -10, 3}, look_at={0, 20, 3}, fov=55},
  lights = {point_light{pos={20, -20, 30}, intensity=0.9}},
  fog = {color={0.72, 0.75, 0.8}, distance=25},
}
