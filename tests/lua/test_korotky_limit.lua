-- korotky.conic_arc with T = W (issue 24): the degenerate section AOD of Korotky 2015, Fig. 3c,
-- the infinite weight as the limit of the arcs: the line pair U W V.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy = check.eq, check.near, check.truthy
local same = check.same_within(1e-14)

local A, O, D = P(0, 0, 0), P(1, 0, 1), P(2, 0, 0)
local c, w, kind = korotky.conic_arc(A, O - A, D, O - D, O)
eq(w, math.huge, "T = W: the weight is infinite")
eq(kind, "line pair", "the degenerate hyperbola AOD")
same(c(0), A, "starts at A")
same(c(0.5), O, "the corner O at the middle")
same(c(0.25), P(0.5, 0, 0.5), "on AO")
same(c(0.75), P(1.5, 0, 0.5), "on OD")
same(c(1), D, "ends at D")
-- arcs with T approaching W lie ever closer to the line pair
local prev = math.huge
for k = 1, 4 do
  local e = 10 ^ -k
  local a, wk = korotky.conic_arc(A, O - A, D, O - D, P(1, 0, 1 - e))
  truthy(wk > 1 and wk < math.huge, "a hyperbola of large weight")
  local worst = 0
  for i = 0, 32 do
    local m = a(i / 32)
    local d = math.min(math.abs(m.z - m.x), math.abs(m.z - (2 - m.x)))   -- off the lines z = x, z = 2 - x
    worst = math.max(worst, d / math.sqrt(2))
  end
  truthy(worst < prev and worst <= 2 * e, "within " .. 2 * e .. " of the line pair")
  prev = worst
end
-- dome_tri's parameters (issue 24: undocumented): the plan point is A + (B - A) u(1 - v) + (C - A) uv
local TA, TB, TC = P(0, 0), P(4, 0), P(1, 3)
local dome = korotky.dome_tri(TA, TB, TC, 2)
for _, uv in ipairs{{0.3, 0.2}, {0.7, 0.6}, {1, 0.5}, {0.5, 1}} do
  local m = dome(uv[1], uv[2])
  local g = TA + (TB - TA) * (uv[1] * (1 - uv[2])) + (TC - TA) * (uv[1] * uv[2])
  near(m.x, g.x, 1e-12, "dome_tri x at " .. uv[1] .. ", " .. uv[2])
  near(m.y, g.y, 1e-12, "dome_tri y")
end
near(dome(1, 0.5).z, 0, 1e-12, "u = 1 is the side BC, on the ground")
check.done()
