-- A honeycomb panel: hexagonal cells laid side by side on a base plate,
-- each cell extruded on its own, as a script in OpenSCAD's style builds
-- them. The cells' corners are computed with cos and sin, so
-- neighbouring cells meet only to rounding; for export the cells, which
-- stand on one plane with one height, are made as one extrusion of the
-- union of their hexagons, whose corners are welded where rounding kept
-- them apart (docs/cli.md, "Contacts"): the mesh is one solid, the
-- cells' walls shared, not cut apart by slits.
--   csgray render examples/honeycomb_panel.lua -o honeycomb_panel.png
--   csgray export examples/honeycomb_panel.lua -o honeycomb_panel.stl
local columns, rows = 5, 4          -- cells across and up
local radius, height, hole = 6, 8, 4.5  -- a cell's corner radius, its height, its hole's
local base = 2                      -- the plate under the cells

local function hexagon(r)
  local corners = {}
  for k = 0, 5 do
    corners[#corners + 1] = {r * math.cos(math.rad(60 * k)), r * math.sin(math.rad(60 * k))}
  end
  return polygon(corners)
end

local cells = {}
local across, up = 1.5 * radius, math.sqrt(3) * radius
for i = 0, columns - 1 do
  for j = 0, rows - 1 do
    cells[#cells + 1] = linear_extrude{hexagon(radius) - hexagon(hole), height = height}
      :translate(across * i, up * j + (i % 2) * up / 2, base)
  end
end
local plate = box{size = {across * (columns - 1) + 2 * radius, up * rows + up / 2, base}}
  :translate(-radius, -up / 2, 0)
local panel = plate + union(table.unpack(cells))

return scene{
  objects = {panel:material{color = {0.95, 0.72, 0.2}, specular = 0.4, shininess = 30},
             plane{}:material{color = {0.9, 0.9, 0.9}}},
  camera = camera{eye = {60, -75, 85}, look_at = {26, 22, 2}, up = {0, 0, 1}, fov = 40},
  lights = {point_light{pos = {90, -60, 140}, intensity = 1},
            point_light{pos = {-60, -40, 70}, intensity = 0.4}},
}
