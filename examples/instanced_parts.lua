-- instanced_parts.lua: one part used many times. A peg (a post with a ball
-- on it) is made once; a row is n moved uses of the peg, the board n moved
-- uses of the row. Moving a union shares it rather than copying it, so the
-- peg and the row are each stored once: -D n=500 shows 250 000 pegs in
-- about the memory of a few.
--   csgray render examples/instanced_parts.lua -D n=500 -o pegs.png
local n = n or 4
local spacing = 4
local peg = cylinder{r = 1, h = 4} + sphere{r = 1.5}:translate(0, 0, 4)
local pegs = {}
for i = 0, n - 1 do pegs[#pegs + 1] = peg:translate(spacing * (i + 0.5), 0, 0) end
local row = union(pegs)
local rows = {}
for j = 0, n - 1 do rows[#rows + 1] = row:translate(0, spacing * (j + 0.5), 0) end
-- The pegs stand half a unit deep in the board, so that they join it.
local board = box{size = {n * spacing, n * spacing, 2}} + union(rows):translate(0, 0, 1.5)
return board:material{color = "steelblue", specular = 0.5, shininess = 40}
