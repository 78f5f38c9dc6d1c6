-- Filled paths through Lua: fill(points [, colour [, rule]]) and path(points, {fill =, color =}):
-- exact pixels (pixel centres inside; left and top edges in, right and bottom out), subpaths
-- and the two rules, true colours, 3-D points through the camera, the SVG element, and every
-- argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

local function ink(colour, w, h)
  local n = 0
  for y = 0, h - 1 do for x = 0, w - 1 do if point(x, y) == colour then n = n + 1 end end end
  return n
end

-- the triangle (0, 0), (6, 0), (0, 6): row y holds the centres 0 <= x < 6 - y (21 pixels)
screen{width = 10, height = 10}
fill({P(0, 0), P(6, 0), P(0, 6)}, 4)
check.eq(ink(4, 10, 10), 21, "triangle: 21 pixels")
for y = 0, 9 do
  for x = 0, 9 do
    check.eq(point(x, y) == 4, y < 6 and x < 6 - y, "triangle pixel " .. x .. "," .. y)
  end
end
check.eq(select(1, last_point()), 0, "the graphics cursor: the last point (x)")
check.eq(select(2, last_point()), 6, "the graphics cursor: the last point (y)")

-- the default colour is the drawing colour; coordinates as numbers in points
screen{width = 10, height = 10}
fill({P(2, 2), P(5, 2), P(5, 4), P(2, 4)})
check.eq(ink(15, 10, 10), 6, "default colour 15: centres 2..4 by 2..3")

-- a square with a hole: two subpaths; even-odd (the default) leaves the hole, nonzero fills it
-- when both run the same way
local outer = {P(1, 1), P(9, 1), P(9, 9), P(1, 9)}
local inner = {P(3, 3), P(7, 3), P(7, 7), P(3, 7)}
screen{width = 10, height = 10}
fill({outer, inner}, 2)
check.eq(ink(2, 10, 10), 48, "even-odd: 64 - 16 pixels")
check.eq(point(5, 5), 0, "even-odd: the hole is empty")
screen{width = 10, height = 10}
fill({outer, inner}, 2, "nonzero")
check.eq(ink(2, 10, 10), 64, "nonzero, same orientation: no hole")
screen{width = 10, height = 10}
fill({outer, {P(3, 3), P(3, 7), P(7, 7), P(7, 3)}}, 2, "nonzero")
check.eq(ink(2, 10, 10), 48, "nonzero, opposite orientation: the hole")
screen{width = 10, height = 10}
fill({outer, inner}, 2, "evenodd")
check.eq(ink(2, 10, 10), 48, "evenodd by name")

-- two triangles sharing an edge cover the square exactly once: each pixel in one colour
screen{width = 12, height = 12}
fill({P(1.5, 1.25), P(10.5, 2), P(9.75, 10.5)}, 3)
fill({P(1.5, 1.25), P(9.75, 10.5), P(2.25, 9.5)}, 5)
local both = ink(3, 12, 12) + ink(5, 12, 12)
screen{width = 12, height = 12}
fill({P(1.5, 1.25), P(10.5, 2), P(9.75, 10.5), P(2.25, 9.5)}, 6)
check.eq(both, ink(6, 12, 12), "two triangles = their quadrilateral, pixel for pixel")

-- path with fill: the fill, and its outline on top only when color is given
screen{width = 12, height = 12}
path({P(1, 1), P(10, 1), P(10, 10), P(1, 10)}, {fill = "#ff8000"})
check.eq(point(5, 5), 256, "path fill: a true colour")
check.eq(point(1, 1), 256, "path fill without color: no outline (top-left corner filled)")
check.eq(point(10, 5), 0, "path fill without color: the right edge is outside")
path({P(1, 1), P(10, 1), P(10, 10), P(1, 10)}, {fill = 1, color = 14})
check.eq(point(5, 5), 1, "path fill inside")
check.eq(point(10, 5), 14, "path outline on top (right side)")
check.eq(point(1, 1), 14, "path outline closed (corner)")
check.eq(point(5, 10), 14, "path outline closed (bottom)")
-- several subpaths with a rule
screen{width = 10, height = 10}
path({outer, inner}, {fill = 2, rule = "nonzero"})
check.eq(ink(2, 10, 10), 64, "path: rule nonzero")

-- VIEW clips; WINDOW maps
screen{width = 10, height = 10}
view(2, 3, 6, 5, nil, nil, "screen")
fill({P(-100, -100), P(100, -100), P(0, 100)}, 5)
check.eq(ink(5, 10, 10), 15, "clipped to the 5 x 3 view")
view()
screen{width = 11, height = 11}
window(0, 0, 10, 10)
fill({P(2, 2), P(5, 2), P(5, 4), P(2, 4)}, 6)
window()
check.eq(ink(6, 11, 11), 6, "window: screen x 2..5, y 6..8 -> 3 x 2 centres")
check.eq(point(2, 6), 6, "window: top-left pixel")

-- 3-D points through the camera
screen{width = 10, height = 10}
camera(map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}))
fill({P(0, 0, 5), P(6, 0, 1), P(0, 6, -2)}, 4)
camera(nil)
check.eq(ink(4, 10, 10), 21, "3-D triangle through the camera")

-- the SVG: one filled path with the fill rule
screen{width = 20, height = 20}
fill({outer, inner}, "#12807f")
fill({P(5, 5), P(9, 5), P(9, 9)}, 14, "nonzero")
local tmp = os.tmpname()
save(tmp .. ".svg")
local f = assert(io.open(tmp .. ".svg"))
local svg = f:read("a")
f:close()
os.remove(tmp .. ".svg")
os.remove(tmp)
check.truthy(svg:find('<path fill="#12807f" fill-rule="evenodd" shape-rendering="crispEdges" d="M1.5 1.5L9.5 1.5L9.5 9.5L1.5 9.5ZM3.5 3.5L7.5 3.5L7.5 7.5L3.5 7.5Z"/>', 1, true),
  "SVG: the even-odd path")
check.truthy(svg:find('<path fill="#ffff55" shape-rendering="crispEdges" d="M5.5 5.5L9.5 5.5L9.5 9.5Z"/>', 1, true),
  "SVG: the nonzero path (SVG's default rule)")

-- errors
screen(12)
check.err(function() fill() end, "fill: argument #1 (points) must be a list of 2-D points, got nil", "no points")
check.err(function() fill({}) end, "fill: argument #1 (points) must be a list of at least one point, got table", "empty")
check.err(function() fill({1, 2}) end, "fill: argument #1 (points) [1] must be a 2-D point, got 1", "numbers")
check.err(function() fill({{P(1, 1)}, 3}) end, "fill: argument #1 (points) [2] must be a list of 2-D points or a list of such lists, got 3", "mixed list")
check.err(function() fill({{P(1, 1)}, {}}) end, "fill: argument #1 (points) [2] must be a list of 2-D points or a list of such lists, got an empty list", "empty subpath")
check.err(function() fill({{P(1, 1)}, {P(1, 1), "x"}}) end, "fill: argument #1 (points) [2][2] must be a 2-D point, got string", "subpath element")
check.err(function() fill({P(0, 0, 0), P(1, 1, 1)}) end, "fill: argument #1 (points) [1] must be a 2-D point, got the 3-D P(0, 0, 0) (3-D points need a camera)", "3-D without a camera")
check.err(function() fill({P(0, 0), V(1, 1)}) end, "fill: argument #1 (points) [2]: V(1, 1) has weight 0, not 1", "a vector")
check.err(function() fill({P(0, 0), P(1, 1) * 2}) end, "fill: argument #1 (points) [2]: 2*P(1, 1) has weight 2, not 1", "a weighted value")
check.err(function() fill({P(1, 1)}, 16) end, "fill: argument #2 (colour) must be a colour number 0..15 or \"#rrggbb\", got 16", "colour")
check.err(function() fill({P(1, 1)}, "#12345") end, "fill: argument #2 (colour) must be a colour number 0..15 or \"#rrggbb\", got \"#12345\"", "colour string")
check.err(function() fill({P(1, 1)}, 1, "odd") end, "fill: argument #3 (rule) must be \"evenodd\" or \"nonzero\", got \"odd\"", "rule")
check.err(function() fill({P(1, 1)}, 1, true) end, "fill: argument #3 (rule) must be \"evenodd\" or \"nonzero\", got boolean", "rule type")
check.err(function() fill({P(0, 0), P(2e15, 0), P(0, 5)}) end, "fill: point 2 lies too far outside the screen (beyond 1e+15 pixels) to place the fill to the pixel", "too far")
check.err(function() path({P(1, 1)}, {fill = "red"}) end, "path: option 'fill' must be a colour number 0..15 or \"#rrggbb\", got \"red\"", "path fill colour")
check.err(function() path({P(1, 1)}, {fill = 1, rule = 2}) end, "path: option 'rule' must be \"evenodd\" or \"nonzero\", got 2", "path rule")
check.err(function() path({P(1, 1)}, 5) end, "path: argument #2 (options) must be a table {closed =, color =, fill =, rule =, arrow =}, got 5", "path options")
camera(map.matrix({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}))
check.err(function() fill({P(0, 0, 0), P(5, 0, 1), P(0, 5, 2)}) end, "fill: argument #1 (points) [1]: P(0, 0, 0) projects to infinity", "vanishing plane")
camera(nil)

check.done()
