-- The script library, part 1: graphs of functions of two variables,
-- parametric surfaces and fractal mountains, as closed triangle meshes
-- (polyhedron{}) or as open surfaces (mesh_surface{}). Written in the
-- script language and run in the script's sandbox, so a user's function
-- is charged to the script's budget like any other code. Errors name the line of the script that called the
-- library.

local function finite(x)
  return type(x) == "number" and x == x and x ~= math.huge and x ~= -math.huge
end

-- Raises "name: message". Each library function is called through a C
-- function (script/standard_library.cpp) that puts the script's file and
-- line in front of a message that begins with "\1": the calling line
-- also when the script's call is a tail call (`return graph{...}`),
-- which leaves no frame of the script for error levels to find.
local function refuse(name, message)
  error("\1" .. name .. ": " .. message, 0)
end

-- {lo, hi} of a table argument, or nil and why not.
local function range(value, what)
  if type(value) ~= "table" or not finite(value[1]) or not finite(value[2]) then
    return nil, nil, what .. " must be {" .. what .. "0, " .. what .. "1}, two numbers"
  end
  if not (value[1] < value[2]) then
    return nil, nil, what .. " must run from a smaller number to a larger one (got {" ..
        value[1] .. ", " .. value[2] .. "})"
  end
  return value[1], value[2]
end

-- The function and the two ranges of graph{} and parametric{}: f, the
-- low and high ends of the first range, then of the second, or a refusal.
local function functionOverRanges(name, args, usage, a, b)
  if type(args) ~= "table" then refuse(name, "takes a table: " .. usage) end
  if type(args.f) ~= "function" then
    refuse(name, "f must be a function of " .. a .. " and " .. b)
  end
  local a0, a1, whyA = range(args[a], a)
  if whyA then refuse(name, whyA) end
  local b0, b1, whyB = range(args[b], b)
  if whyB then refuse(name, whyB) end
  return args.f, a0, a1, b0, b1
end

-- polyhedron{} or mesh_surface{} (`maker`, named `makerName`) called for
-- a library function: its error, if any, comes back as the library
-- function's own, at the script's line.
local function made(name, maker, makerName, args)
  local ok, result = pcall(maker, args)
  if not ok then
    local message = tostring(result):gsub("^[^:]*:%d+: ", ""):gsub("^" .. makerName .. ": ", "")
    refuse(name, message)
  end
  return result
end

local function solidOf(name, points, faces)
  return made(name, polyhedron, "polyhedron", {points = points, faces = faces})
end

-- The open surface of the triangles (mesh_surface{}), with a normal per
-- point (or none: averaged from the triangles), smooth unless `smooth` is
-- false.
local function surfaceOf(name, points, faces, normals, smooth)
  return made(name, mesh_surface, "mesh_surface",
              {points = points, faces = faces, normals = normals, smooth = smooth})
end

-- The options that choose a surface rather than a solid: surface=true
-- (then no base) and smooth=false (flat triangles). Returns surface, smooth.
local function surfaceOptions(name, args)
  if args.surface ~= nil and type(args.surface) ~= "boolean" then
    refuse(name, "surface must be true or false")
  end
  if args.smooth ~= nil and type(args.smooth) ~= "boolean" then
    refuse(name, "smooth must be true or false")
  end
  if args.surface and args.base ~= nil then
    refuse(name, "a surface (surface=true) has no base: give one or the other")
  end
  if args.smooth ~= nil and not args.surface then
    refuse(name, "smooth is for a surface (surface=true); a solid's faces are flat")
  end
  return args.surface == true, args.smooth ~= false
end

-- The derivative of g (a function of one number giving a number or a
-- list of numbers) at t in [t0, t1], by central differences of step h
-- (h of about the cube root of the rounding error of a double times the
-- range balances the two errors: Press et al., "Numerical Recipes",
-- 3rd ed., 5.7), one-sided at the ends. Returns a list of numbers.
local function derivative(g, t, t0, t1)
  local h = 1e-5 * (t1 - t0)
  local a, b = math.max(t0, t - h), math.min(t1, t + h)
  local ga, gb = g(a), g(b)
  if type(ga) == "number" then ga, gb = {ga}, {gb} end
  local d = {}
  for k = 1, #ga do d[k] = (gb[k] - ga[k]) / (b - a) end
  return d
end

-- The closed solid under a height field: the top surface (triangles over
-- points {x, y, z}, counter-clockwise seen from above), vertical walls
-- down from its boundary and a flat base at height `base`, which must lie
-- below `lowest`, the lowest point (of the `what`: "graph"). Returns the
-- solid, or refuses with why not.
local function solidUnder(name, what, points, triangles, base, lowest)
  if not (base < lowest) then
    refuse(name, "base must lie below the lowest point of the " .. what .. " (" .. lowest .. ")")
  end
  -- The boundary: directed edges of the top that no triangle runs back
  -- along; seen from above they go round counter-clockwise.
  local count = #points
  local used = {}
  for _, t in ipairs(triangles) do
    for k = 1, 3 do
      used[t[k] * count + t[k % 3 + 1]] = true
    end
  end
  local after, first = {}, nil
  for _, t in ipairs(triangles) do
    for k = 1, 3 do
      local a, b = t[k], t[k % 3 + 1]
      if not used[b * count + a] then
        after[a] = b
        first = first or a
      end
    end
  end
  local all, faces = {}, {}
  for i, p in ipairs(points) do
    all[i] = p
  end
  for _, t in ipairs(triangles) do
    faces[#faces + 1] = {t[1], t[2], t[3]}
  end
  -- Each boundary point's twin on the base, and the base's middle.
  local below, lo, hi = {}, {math.huge, math.huge}, {-math.huge, -math.huge}
  local v = first
  repeat
    local p = points[v + 1]
    all[#all + 1] = {p[1], p[2], base}
    below[v] = #all - 1
    lo = {math.min(lo[1], p[1]), math.min(lo[2], p[2])}
    hi = {math.max(hi[1], p[1]), math.max(hi[2], p[2])}
    v = after[v]
  until v == first or v == nil
  if v == nil then refuse(name, "the surface's boundary is not one loop") end
  all[#all + 1] = {(lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2, base}
  local middle = #all - 1
  v = first
  repeat
    local w = after[v]
    -- The wall under edge v → w, counter-clockwise seen from outside, and
    -- the base's triangle, counter-clockwise seen from below.
    faces[#faces + 1] = {below[v], below[w], w}
    faces[#faces + 1] = {below[v], w, v}
    faces[#faces + 1] = {middle, below[w], below[v]}
    v = w
  until v == first
  return solidOf(name, all, faces)
end

-- graph{f=function(x, y) return z end, x={x0, x1}, y={y0, y1},
--   resolution=16, tolerance=0.01, base=, surface=false, smooth=true}
-- The solid under z = f(x, y) over the rectangle, down to `base` (by
-- default a twentieth of the rectangle's larger side below the lowest
-- point); with surface=true the graph's sheet alone, an open surface
-- whose normals come from f's derivatives. The top starts as a grid of
-- resolution × resolution cells, each cut into two triangles along a
-- diagonal, and is refined where f bends
-- away from the triangles: a triangle whose edge midpoints lie farther
-- than `tolerance` from it (in z) is cut in two through the middle of its
-- refinement edge, the newest-vertex bisection of Mitchell ("Adaptive
-- refinement for arbitrary finite-element spaces with hierarchical
-- bases", J. Comput. Appl. Math. 36, 1991), which keeps the mesh free of
-- hanging points. At most 200 000 triangles.
function graph(args)
  local name = "graph"
  local f, x0, x1, y0, y1 = functionOverRanges(name, args,
      "graph{f=function(x, y) return ... end, x={x0, x1}, y={y0, y1}}", "x", "y")
  local n = args.resolution or 16
  if not finite(n) or n ~= math.floor(n) or n < 1 or n > 1024 then
    refuse(name, "resolution must be a whole number from 1 to 1024 (got " .. tostring(n) .. ")")
  end
  local tolerance = args.tolerance or 0.01
  if not finite(tolerance) or tolerance <= 0 then
    refuse(name, "tolerance must be a positive number (got " .. tostring(tolerance) .. ")")
  end
  if args.base ~= nil and not finite(args.base) then refuse(name, "base must be a number") end
  local asSurface, smooth = surfaceOptions(name, args)

  local points = {}
  local problem = nil
  local function height(x, y)
    local z = f(x, y)
    if not finite(z) and not problem then
      problem = "f(" .. x .. ", " .. y .. ") gave " .. tostring(z) .. ", not a number"
    end
    return finite(z) and z or 0
  end
  local function addPoint(x, y)
    points[#points + 1] = {x, y, height(x, y)}
    return #points - 1
  end
  -- Triangles: {apex, u, v}, counter-clockwise seen from above, cut
  -- through the middle of u–v. owner[a·K + b] is the triangle that runs
  -- along a → b.
  local K = 1 << 26
  local triangles, alive, owner, middleOf = {}, {}, {}, {}
  local function addTriangle(apex, u, v)
    triangles[#triangles + 1] = {apex, u, v}
    local t = #triangles
    alive[t] = true
    owner[apex * K + u], owner[u * K + v], owner[v * K + apex] = t, t, t
    return t
  end
  local function middle(a, b)
    local key = math.min(a, b) * K + math.max(a, b)
    local m = middleOf[key]
    if not m then
      local p, q = points[a + 1], points[b + 1]
      m = addPoint((p[1] + q[1]) / 2, (p[2] + q[2]) / 2)
      middleOf[key] = m
    end
    return m
  end
  for j = 0, n do
    for i = 0, n do
      addPoint(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * j / n)
    end
  end
  for j = 0, n - 1 do
    for i = 0, n - 1 do
      local a, b = j * (n + 1) + i, j * (n + 1) + i + 1
      local c, d = b + n + 1, a + n + 1
      addTriangle(b, c, a)
      addTriangle(d, a, c)
    end
  end
  if problem then refuse(name, problem) end

  local function split(t)
    local apex, u, v = triangles[t][1], triangles[t][2], triangles[t][3]
    local m = middle(u, v)
    alive[t] = false
    owner[u * K + v] = nil
    return addTriangle(m, apex, u), addTriangle(m, v, apex)
  end
  -- Cuts t, first cutting the neighbour across its refinement edge until
  -- that neighbour's refinement edge is the same one, then both.
  local limit = 200000
  local function refine(t)
    local u, v = triangles[t][2], triangles[t][3]
    local across = owner[v * K + u]
    while across and not (triangles[across][2] == v and triangles[across][3] == u) do
      refine(across)
      across = owner[v * K + u]
    end
    if alive[t] then split(t) end
    if across and alive[across] then split(across) end
  end
  -- How far f's values at t's edge midpoints are from the triangle's.
  local function deviation(t)
    local worst = 0
    local c = triangles[t]
    for k = 1, 3 do
      local a, b = c[k], c[k % 3 + 1]
      local m = middle(a, b)
      local zm = (points[a + 1][3] + points[b + 1][3]) / 2
      worst = math.max(worst, math.abs(points[m + 1][3] - zm))
    end
    return worst
  end
  local t = 1
  while t <= #triangles and #triangles < limit do
    if alive[t] and deviation(t) > tolerance then refine(t) end
    t = t + 1
  end
  if problem then refuse(name, problem) end

  -- The points the remaining triangles use (a midpoint measured for an
  -- edge that was never cut is not one), renumbered.
  local renumbered, used, top = {}, {}, {}
  local lowest = math.huge
  for i, c in ipairs(triangles) do
    if alive[i] then
      local r = {}
      for k = 1, 3 do
        local p = c[k]
        if not renumbered[p] then
          used[#used + 1] = points[p + 1]
          renumbered[p] = #used - 1
          lowest = math.min(lowest, points[p + 1][3])
        end
        r[k] = renumbered[p]
      end
      top[#top + 1] = r
    end
  end
  if asSurface then
    -- The normal (−∂f/∂x, −∂f/∂y, 1) at each point.
    local normals = {}
    if smooth then
      for i, p in ipairs(used) do
        local x, y = p[1], p[2]
        local fx = derivative(function(t) return height(t, y) end, x, x0, x1)[1]
        local fy = derivative(function(t) return height(x, t) end, y, y0, y1)[1]
        normals[i] = {-fx, -fy, 1}
      end
      if problem then refuse(name, problem) end
    end
    return surfaceOf(name, used, top, normals, smooth)
  end
  local base = args.base or lowest - 0.05 * math.max(x1 - x0, y1 - y0)
  return solidUnder(name, "graph", used, top, base, lowest)
end

-- parametric{f=function(u, v) return {x, y, z} end, u={u0, u1}, v={v0, v1},
--   resolution={nu, nv}, closed_u=false, closed_v=false, surface=false,
--   smooth=true}
-- The solid bounded by a parametric surface that closes up: a grid of
-- nu × nv cells over the parameter rectangle, each cut into two
-- triangles; with closed_u the cells at u1 join those at u0 (and likewise
-- for v), and points that f puts in one place (the poles of a sphere) are
-- one point. The surface must then be closed, or it is refused with the
-- place of an open edge. With surface=true it is an open surface, closed
-- or not (a Möbius strip, a helicoid), its normals ∂f/∂u × ∂f/∂v.
function parametric(args)
  local name = "parametric"
  local f, u0, u1, v0, v1 = functionOverRanges(name, args,
      "parametric{f=function(u, v) return {x, y, z} end, u={u0, u1}, v={v0, v1}}", "u", "v")
  local resolution = args.resolution or {48, 24}
  if type(resolution) == "number" then resolution = {resolution, resolution} end
  local nu, nv = resolution[1], resolution[2]
  for _, r in ipairs({nu, nv}) do
    if not finite(r) or r ~= math.floor(r) or r < 3 or r > 2048 then
      refuse(name, "resolution must be whole numbers from 3 to 2048 (got " .. tostring(r) .. ")")
    end
  end
  local closedU, closedV = args.closed_u == true, args.closed_v == true
  local asSurface, smooth = surfaceOptions(name, args)

  -- The grid's points, one per place: a point f gives again (to 1e-9 of
  -- the surface's size) is the earlier one.
  local raw = {}
  local lo, hi = {math.huge, math.huge, math.huge}, {-math.huge, -math.huge, -math.huge}
  -- f(u, v), or a refusal where it is not a point.
  local function point(u, v)
    local p = f(u, v)
    if type(p) ~= "table" or not finite(p[1]) or not finite(p[2]) or not finite(p[3]) then
      refuse(name, "f(" .. u .. ", " .. v .. ") must give {x, y, z}, three numbers")
    end
    return p
  end
  for j = 0, nv do
    for i = 0, nu do
      local u, v = u0 + (u1 - u0) * i / nu, v0 + (v1 - v0) * j / nv
      local p = point(u, v)
      raw[j * (nu + 1) + i] = {p[1], p[2], p[3]}
      for k = 1, 3 do
        lo[k], hi[k] = math.min(lo[k], p[k]), math.max(hi[k], p[k])
      end
    end
  end
  local size = math.max(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  if not (size > 0) then refuse(name, "f puts every point in one place") end
  local grain = 1e-9 * size
  local points, index, at, param = {}, {}, {}, {}
  for j = 0, nv do
    for i = 0, nu do
      local g = j * (nu + 1) + i
      if closedU and i == nu then
        index[g] = index[j * (nu + 1)]
      elseif closedV and j == nv then
        index[g] = index[i]
      else
        local p = raw[g]
        local key = string.format("%d,%d,%d", math.floor(p[1] / grain + 0.5),
                                  math.floor(p[2] / grain + 0.5), math.floor(p[3] / grain + 0.5))
        if not at[key] then
          points[#points + 1] = p
          param[#points] = {u0 + (u1 - u0) * i / nu, v0 + (v1 - v0) * j / nv}
          at[key] = #points - 1
        end
        index[g] = at[key]
      end
    end
  end
  local faces = {}
  local function add(a, b, c)
    if a ~= b and b ~= c and c ~= a then faces[#faces + 1] = {a, b, c} end
  end
  for j = 0, nv - 1 do
    for i = 0, nu - 1 do
      local a, b = index[j * (nu + 1) + i], index[j * (nu + 1) + i + 1]
      local c, d = index[(j + 1) * (nu + 1) + i + 1], index[(j + 1) * (nu + 1) + i]
      add(a, b, c)
      add(a, c, d)
    end
  end
  if asSurface then
    -- The normal ∂f/∂u × ∂f/∂v at each point; where it vanishes (a pole,
    -- where a whole edge of the grid is one point) it is left to the
    -- triangles around the point.
    local normals = {}
    if smooth then
      for i, uv in ipairs(param) do
        local u, v = uv[1], uv[2]
        local du = derivative(function(t) return point(t, v) end, u, u0, u1)
        local dv = derivative(function(t) return point(u, t) end, v, v0, v1)
        local n = {du[2] * dv[3] - du[3] * dv[2], du[3] * dv[1] - du[1] * dv[3],
                   du[1] * dv[2] - du[2] * dv[1]}
        local length = math.sqrt(n[1] * n[1] + n[2] * n[2] + n[3] * n[3])
        if not finite(length) then
          refuse(name, "f gave no finite derivative at (" .. u .. ", " .. v .. ")")
        end
        -- A billionth of the largest product: no direction to speak of.
        local scale = math.sqrt((du[1] ^ 2 + du[2] ^ 2 + du[3] ^ 2) *
                                (dv[1] ^ 2 + dv[2] ^ 2 + dv[3] ^ 2))
        normals[i] = length > 1e-9 * scale and n or {0, 0, 0}
      end
    end
    return surfaceOf(name, points, faces, normals, smooth)
  end
  -- Closed: every edge has two faces that run along it the other way.
  local count = #points
  local runs = {}
  for _, t in ipairs(faces) do
    for k = 1, 3 do
      local a, b = t[k], t[k % 3 + 1]
      runs[a * count + b] = (runs[a * count + b] or 0) + 1
    end
  end
  for _, t in ipairs(faces) do
    for k = 1, 3 do
      local a, b = t[k], t[k % 3 + 1]
      if runs[b * count + a] ~= 1 or runs[a * count + b] ~= 1 then
        local p, q = points[a + 1], points[b + 1]
        refuse(name, string.format(
            "the surface does not close up into a solid: the edge from (%g, %g, %g) to " ..
            "(%g, %g, %g) is not between two faces (closed_u and closed_v join the " ..
            "parameter rectangle's opposite sides; surface=true makes an open surface)",
            p[1], p[2], p[3], q[1], q[2], q[3]))
      end
    end
  end
  return solidOf(name, points, faces)
end

-- A number in [-1, 1) from a seed and two whole numbers, the same on every
-- run: a 64-bit mix (SplitMix64's finaliser, Steele, Lea and Flood, "Fast
-- splittable pseudorandom number generators", OOPSLA 2014).
local function noise(seed, i, j)
  local h = seed * 0x9E3779B97F4A7C15 + i * 0xBF58476D1CE4E5B9 + j * 0x94D049BB133111EB
  h = (h ~ (h >> 30)) * 0xBF58476D1CE4E5B9
  h = (h ~ (h >> 27)) * 0x94D049BB133111EB
  h = h ~ (h >> 31)
  return ((h >> 11) * 2.0 ^ -53) * 2 - 1
end

-- fractal_mountain{size=100, levels=6, roughness=0.5, seed=1, base=,
--   surface=false, smooth=true}
-- A square of side `size` from the origin, its height made by midpoint
-- displacement on triangles (Fournier, Fussell and Carpenter, "Computer
-- rendering of stochastic models", CACM 25(6), 1982): the square cut into
-- two triangles, each cut into four at its edges' midpoints `levels`
-- times, each new midpoint raised or lowered from its edge's mean height
-- by a random amount. The first level's amounts are up to a quarter of
-- `size`; each further level's are `roughness` times the last's. The
-- same seed gives the same mountain. A solid down to `base`, or with
-- surface=true the landscape alone, an open surface.
function fractal_mountain(args)
  local name = "fractal_mountain"
  args = args or {}
  if type(args) ~= "table" then refuse(name, "takes a table: fractal_mountain{size=, levels=, roughness=, seed=}") end
  local size, levels = args.size or 100, args.levels or 6
  local roughness, seed = args.roughness or 0.5, args.seed or 1
  if not finite(size) or size <= 0 then refuse(name, "size must be a positive number") end
  if not finite(levels) or levels ~= math.floor(levels) or levels < 1 or levels > 9 then
    refuse(name, "levels must be a whole number from 1 to 9 (got " .. tostring(levels) .. ")")
  end
  if not finite(roughness) or roughness < 0 or roughness > 1 then
    refuse(name, "roughness must be in [0, 1] (got " .. tostring(roughness) .. ")")
  end
  if math.type(seed) ~= "integer" then refuse(name, "seed must be a whole number") end
  if args.base ~= nil and not finite(args.base) then refuse(name, "base must be a number") end
  local asSurface, smooth = surfaceOptions(name, args)

  local n = 1 << levels
  local z = {}
  local function at(i, j) return j * (n + 1) + i end
  z[at(0, 0)], z[at(n, 0)], z[at(0, n)], z[at(n, n)] = 0, 0, 0, 0
  local amount = size / 4
  local step = n
  while step > 1 do
    local half = step // 2
    -- The midpoints of the triangles' edges: horizontal, vertical and the
    -- diagonals (from (i, j) to (i + step, j + step)), each once.
    local function raise(i, j, ai, aj, bi, bj)
      if z[at(i, j)] == nil then
        z[at(i, j)] = (z[at(ai, aj)] + z[at(bi, bj)]) / 2 + amount * noise(seed, i, j)
      end
    end
    for j = 0, n, step do
      for i = 0, n - step, step do raise(i + half, j, i, j, i + step, j) end
    end
    for j = 0, n - step, step do
      for i = 0, n, step do raise(i, j + half, i, j, i, j + step) end
    end
    for j = 0, n - step, step do
      for i = 0, n - step, step do raise(i + half, j + half, i, j, i + step, j + step) end
    end
    amount = amount * roughness
    step = half
  end
  local points, triangles = {}, {}
  local lowest = math.huge
  for j = 0, n do
    for i = 0, n do
      points[at(i, j) + 1] = {size * i / n, size * j / n, z[at(i, j)]}
      lowest = math.min(lowest, z[at(i, j)])
    end
  end
  for j = 0, n - 1 do
    for i = 0, n - 1 do
      local a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
      triangles[#triangles + 1] = {a, b, c}
      triangles[#triangles + 1] = {a, c, d}
    end
  end
  if asSurface then return surfaceOf(name, points, triangles, nil, smooth) end
  local base = args.base or lowest - 0.05 * size
  return solidUnder(name, "mountain", points, triangles, base, lowest)
end

