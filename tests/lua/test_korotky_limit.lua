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
check.done()
