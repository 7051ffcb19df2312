-- quadrics.lua: the nine quadrics of seed 000's table 17.1 on a 3 × 3 grid.
-- All but the ellipsoid are unbounded, so each is clipped to the same
-- 2 × 2 × 2 box; the box's cut faces take the quadric's material. The
-- scene has its own camera and lights: unbounded solids give the automatic
-- camera nothing to frame. The floor lies just below the boxes, so that
-- their bottom faces do not coincide with it.

local unit = {lo={-1, -1, -1}, hi={1, 1, 1}}

local function piece(solid, r, g, b)
  return clip(solid:material{color={r, g, b}, specular=0.3, shininess=40}, unit)
end

local shapes = {
  -- Back row: the closed ellipsoid and the two hyperboloids.
  piece(ellipsoid{radii={0.95, 0.7, 0.8}}, 0.85, 0.25, 0.2),
  piece(hyperboloid1{a=0.45, b=0.45, c=0.5}, 0.9, 0.55, 0.15),
  piece(hyperboloid2{a=0.28, b=0.28, c=0.3}, 0.85, 0.8, 0.2),
  -- Middle row: one nappe of the cone, its apex on the floor of its box (a
  -- double cone's apex is a single point, which cannot be printed: export
  -- refuses it), and the two paraboloids, turned over so that their curved
  -- faces are on top: the elliptic paraboloid is a dome with its vertex at
  -- the top of its box, the saddle the top face.
  piece(elliptic_cone{a=0.8, b=0.6, c=1}:translate(0, 0, -1), 0.35, 0.7, 0.3),
  piece(elliptic_paraboloid{a=0.5, b=0.5}:rotate(180, 0, 0):translate(0, 0, 1), 0.2, 0.65, 0.6),
  piece(hyperbolic_paraboloid{a=1.3, b=1.3}:rotate(180, 0, 0), 0.25, 0.45, 0.85),
  -- Front row: the three cylinders along z. The parabolic cylinder's
  -- vertex line is moved to the back of its box.
  piece(elliptic_cylinder{a=0.9, b=0.55}, 0.45, 0.3, 0.85),
  piece(hyperbolic_cylinder{a=0.35, b=0.5}, 0.7, 0.3, 0.75),
  piece(parabolic_cylinder{p=0.5}:translate(-1, 0, 0), 0.85, 0.35, 0.55),
}

local objects = {}
for i, s in ipairs(shapes) do
  local column, row = (i - 1) % 3, (i - 1) // 3
  objects[i] = s:translate((column - 1) * 3, (1 - row) * 3, 0)
end
objects[#objects + 1] = plane{normal={0, 0, 1}, offset=-1.02}:material{
  color=checker{size=1, colors={{0.55, 0.55, 0.55}, {0.35, 0.35, 0.35}}}}

return scene{
  objects = objects,
  camera = camera{eye={0, -12, 9}, look_at={0, 0.4, -0.6}, fov=52},
  lights = {
    point_light{pos={-8, -10, 14}, intensity=0.8},
    point_light{pos={10, -4, 6}, intensity=0.35},
  },
  background = {0.08, 0.08, 0.12},
}
