-- The outer stack of examples/vase.lua alone: 40 frustums, each standing
-- on the one below on a shared rim.
local function radius(i) return 20 + 6 * math.sin(i * 0.25) end
local layers = {}
for i = 0, 39 do
  layers[#layers + 1] = cylinder{r1=radius(i), r2=radius(i + 1), h=2}:translate(0, 0, 2 * i)
end
return union(layers)
