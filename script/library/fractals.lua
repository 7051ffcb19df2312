-- The script library, part 2: fractal compounds. Each is built from
-- csgray's own shapes by recursion, as a script would build it, and has a
-- `level` (0 is the first shape alone). `finite` and `refuse` come from
-- part 1 (the parts are one chunk).

-- A compound's table of arguments, its level (a whole number from 0 to
-- most) and its size (positive), with their defaults.
local function compoundArguments(name, args, level, most, size)
  args = args or {}
  if type(args) ~= "table" then refuse(name, "takes a table: " .. name .. "{level=, size=}") end
  level, size = args.level or level, args.size or size
  if not finite(level) or level ~= math.floor(level) or level < 0 or level > most then
    refuse(name, "level must be a whole number from 0 to " .. most .. " (got " .. tostring(level) .. ")")
  end
  if not finite(size) or size <= 0 then refuse(name, "size must be a positive number") end
  return args, level, size
end

-- sierpinski_triangle{level=4, size=100}
-- The Sierpinski triangle as one 2D region: the equilateral triangle of
-- side `size` with a corner at the origin and a side on the x axis, less
-- its middle quarter, level times over. One polygon whose paths are the
-- outline and the holes (even-odd), so that an extrusion of it is one
-- exact prism. Its area is (3/4)^level of the triangle's. Its pieces
-- touch at their corners, where an extrusion's mesh would be pinched: it
-- renders exactly, and is refused for export.
function sierpinski_triangle(args)
  local name = "sierpinski_triangle"
  local args, level, size = compoundArguments(name, args, 4, 9, 100)
  local points, paths = {}, {}
  local function add(x, y)
    points[#points + 1] = {x, y}
    return #points - 1
  end
  local function loop(a, b, c)
    paths[#paths + 1] = {add(a[1], a[2]), add(b[1], b[2]), add(c[1], c[2])}
  end
  local function mid(p, q) return {(p[1] + q[1]) / 2, (p[2] + q[2]) / 2} end
  local function cut(a, b, c, depth)
    if depth == 0 then return end
    local ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
    loop(ab, ca, bc)  -- the hole
    cut(a, ab, ca, depth - 1)
    cut(ab, b, bc, depth - 1)
    cut(ca, bc, c, depth - 1)
  end
  local a, b, c = {0, 0}, {size, 0}, {size / 2, size * math.sqrt(3) / 2}
  loop(a, b, c)
  cut(a, b, c, level)
  return polygon{points = points, paths = paths}
end

-- sierpinski_tetrahedron{level=4, size=100}
-- The union of 4^level regular tetrahedra: the tetrahedron of
-- circumradius size/2 (as tetrahedron{r=}) replaced, level times over, by
-- the four of half its size at its corners, which touch at their corners.
-- Its volume is (1/2)^level of the first's. Built from the smallest up:
-- above level 4, each level is four moved uses of the level below, which
-- a transform shares rather than copies, so memory grows with the level,
-- not with the 4^level tetrahedra it shows.
function sierpinski_tetrahedron(args)
  local name = "sierpinski_tetrahedron"
  local args, level, size = compoundArguments(name, args, 4, 10, 100)
  -- tetrahedron{r=1}'s corners: (0, 0, 1) and three on z = -1/3 at
  -- distance 2√2/3 from the axis, one of them in the xz plane at x > 0.
  local corners = {{0, 0, 1}}
  for k = 0, 2 do
    local angle = 2 * math.pi * k / 3
    corners[#corners + 1] = {2 * math.sqrt(2) / 3 * math.cos(angle),
                             2 * math.sqrt(2) / 3 * math.sin(angle), -1 / 3}
  end
  -- The first levels as one flat union of moved tetrahedra (a ray finds
  -- its few among them through the union's BVH, faster than through
  -- nested uses); above them each level is four moved uses of the level
  -- below, of circumradius r, at the corners of the tetrahedron of
  -- circumradius 2r about the same centre: r times each.
  local flat = math.min(level, 4)
  local r = size / 2 / 2 ^ (level - flat)
  local pieces = {}
  local function place(x, y, z, s, depth)
    if depth == 0 then
      pieces[#pieces + 1] = tetrahedron{r = s}:translate(x, y, z)
      return
    end
    for _, c in ipairs(corners) do
      place(x + c[1] * s / 2, y + c[2] * s / 2, z + c[3] * s / 2, s / 2, depth - 1)
    end
  end
  place(0, 0, 0, r, flat)
  local part = #pieces == 1 and pieces[1] or union(table.unpack(pieces))
  for _ = flat + 1, level do
    local uses = {}
    for _, c in ipairs(corners) do
      uses[#uses + 1] = part:translate(c[1] * r, c[2] * r, c[3] * r)
    end
    part = union(table.unpack(uses))
    r = 2 * r
  end
  return part
end

-- The squares of a Pythagoras tree (Bosman, 1942) in the plane: each
-- square stands on the segment p → q (its side to the left of it), and
-- carries on its far side a right triangle with angle `angle` at its left
-- corner, whose legs carry the next two squares. Calls square(p, q, depth)
-- for each, from the trunk down.
local function pythagorasSquares(p, q, angle, level, square)
  local c, s = math.cos(angle), math.sin(angle)
  local function grow(p, q, depth)
    square(p, q, depth)
    if depth == level then return end
    local dx, dy = q[1] - p[1], q[2] - p[2]
    local p2, q2 = {p[1] - dy, p[2] + dx}, {q[1] - dy, q[2] + dx}
    -- The triangle's apex: from p2 along the side turned by angle, cos(angle) of its length.
    local apex = {p2[1] + c * (c * dx - s * dy), p2[2] + c * (s * dx + c * dy)}
    grow(p2, apex, depth + 1)
    grow(apex, q2, depth + 1)
  end
  grow(p, q, 0)
end

local function treeAngle(name, angle)
  if not finite(angle) or angle <= 0 or angle >= 90 then
    refuse(name, "angle must be between 0 and 90 degrees (got " .. tostring(angle) .. ")")
  end
  return math.rad(angle)
end

-- pythagoras_tree{level=6, size=10, angle=45}
-- The Pythagoras tree as a 2D region: the union of its 2^(level+1) − 1
-- squares, the trunk of side `size` on the x axis from the origin. The two
-- squares on each square's far side have sides cos(angle) and sin(angle)
-- times its own, so each level adds the trunk's area again (Pythagoras):
-- level + 1 times it in all, until branches meet (about level 5 at 45°).
function pythagoras_tree(args)
  local name = "pythagoras_tree"
  local args, level, size = compoundArguments(name, args, 6, 12, 10)
  local angle = treeAngle(name, args.angle or 45)
  local squares = {}
  pythagorasSquares({0, 0}, {size, 0}, angle, level, function(p, q)
    local dx, dy = q[1] - p[1], q[2] - p[2]
    squares[#squares + 1] = polygon{{p[1], p[2]}, {q[1], q[2]}, {q[1] - dy, q[2] + dx},
                                    {p[1] - dy, p[2] + dx}}
  end)
  if #squares == 1 then return squares[1] end
  return union(table.unpack(squares))
end

-- pythagoras_tree_3d{level=5, size=10, angle=45}
-- A Pythagoras tree of cubes: the trunk is the cube of side `size` on
-- the origin's corner, and each cube carries two cubes tilted as the
-- squares of the plane tree are, in a plane that turns a quarter turn
-- about the vertical at each level, so that the tree branches in space.
-- Each cube sinks a hundredth of its side into the one below it.
function pythagoras_tree_3d(args)
  local name = "pythagoras_tree_3d"
  local args, level, size = compoundArguments(name, args, 5, 10, 10)
  local angle = treeAngle(name, args.angle or 45)
  local degrees = math.deg(angle)
  local c, s = math.cos(angle), math.sin(angle)
  -- The tree of the unit cube [0, 1]³, in its own frame; each child's
  -- frame is turned a quarter turn about its vertical axis. Both children
  -- are moved uses of one subtree, which transforms share, so the part
  -- holds one subtree per level.
  local function tree(depth)
    local cube = box{size = {1, 1, 1}}
    if depth == level then return cube end
    -- Each child sinks a hundredth of its side into its parent, so that
    -- the two overlap rather than touch at a hair's breadth (their faces
    -- in one plane, as the tilts leave them, only up to rounding), which
    -- is what an export can join.
    local below = tree(depth + 1):translate(-0.5, -0.5, -0.01):rotate(0, 0, 90):translate(0.5, 0.5, 0)
    -- Left: scaled by cos, its x axis turned up by angle, on the top's
    -- left edge; right: scaled by sin, turned down by 90° − angle, on the
    -- apex. Both centred on the top in y.
    local left = below:scale(c):rotate(0, -degrees, 0):translate(0, (1 - c) / 2, 1)
    local right = below:scale(s):rotate(0, 90 - degrees, 0):translate(c * c, (1 - s) / 2, 1 + c * s)
    return cube + left + right
  end
  return tree(0):scale(size)
end
