-- A knob: a cylinder whose top edge is rounded by a torus fillet, with 24
-- knurl grooves (cylinders) that end exactly on the line where the fillet
-- meets the side, tangentially.
local R, H, f = 15, 12, 2
local body = cylinder{r=R, h=H - f} + cylinder{r=R - f, h=H}
  + torus{R=R - f, r=f}:translate(0, 0, H - f)
local grooves = {}
for i = 0, 23 do
  grooves[#grooves + 1] = cylinder{r=0.6, h=H - f}:translate(R, 0, 0):rotate(0, 0, i * 15)
end
return body - union(grooves)
