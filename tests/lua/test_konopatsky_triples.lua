-- The symbolic method of §2.2 (issue 23): a table of triples becomes its construction
-- (conic.scheme); Baluba's systems (a) Pascal and (b) of Fig. 2.28.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-10)

local pts = {A1 = P(0, 0), A2 = P(1.2, 2.1), A3 = P(3, 2.9), A4 = P(4.6, 1.8), A5 = P(5, 0)}
-- (b): A1AB, A2BC, A3A2A, A4A5A, A5A1C, MA3B, MA4C, C = A1 t' + A5 t
local b, steps = conic.scheme{
  triples = {{"A1", "A", "B"}, {"A2", "B", "C"}, {"A3", "A2", "A"}, {"A4", "A5", "A"},
             {"A5", "A1", "C"}, {"M", "A3", "B"}, {"M", "A4", "C"}},
  points = pts, current = {"C", "A1", "A5"}, result = "M", range = {0.05, 0.95}}
eq(#steps, 3, "three meets")
eq(steps[1], "A = A3A2 x A4A5", "A first, the fixed point of (b)")
local ref = conic.triples(pts.A1, pts.A2, pts.A3, pts.A4, pts.A5)
for _, t in ipairs{0.1, 0.3, 0.5, 0.8} do same(b(t), ref(t), "(b) = conic.triples at " .. t) end
-- (a): Pascal, C on A3A4; M on the conic through A1..A5
local a = conic.scheme{
  triples = {{"A1", "A2", "A"}, {"A2", "A3", "B"}, {"A3", "A4", "C"}, {"A4", "A5", "A"},
             {"A5", "M", "B"}, {"M", "A1", "C"}, {"A", "C", "B"}},
  points = pts, current = {"C", "A3", "A4"}, result = "M", range = {-0.5, 1.5}}
local e = conic.elements(pts.A1, pts.A2, pts.A3, pts.A4, pts.A5)
local q = e.coef
for _, t in ipairs{-0.3, 0.2, 0.6, 1.3} do
  local m = a(t)
  near(q[1] * m.x ^ 2 + q[2] * m.x * m.y + q[3] * m.y ^ 2 + q[4] * m.x + q[5] * m.y + q[6], 0, 1e-10,
       "(a) Pascal: M on the conic through A1..A5 at " .. t)
end
-- the one weight rule: a point of weight 1 - 1e-12 (a computed one) is a point
local pts2 = {A1 = P(0, 0) * (1 - 1e-12), A2 = pts.A2, A3 = pts.A3, A4 = pts.A4, A5 = pts.A5}
local b2 = conic.scheme{
  triples = {{"A1", "A", "B"}, {"A2", "B", "C"}, {"A3", "A2", "A"}, {"A4", "A5", "A"},
             {"A5", "A1", "C"}, {"M", "A3", "B"}, {"M", "A4", "C"}},
  points = pts2, current = {"C", "A1", "A5"}, result = "M", range = {0.05, 0.95}}
same(b2(0.3), b(0.3), "a near-1 weight accepted as a point")
err(function() conic.scheme{triples = {{"A1", "A2", "A"}}, points = {A1 = V(1, 0)}, current = {"C", "A1", "A2"}, result = "M"} end,
    "conic.scheme: points.A1 must be a 2-D or more point", "a vector among the points")
err(function() conic.scheme{triples = {{"A1", "A2", "A"}, {"M", "A1", "C"}}, points = pts, current = {"C", "A3", "A4"}, result = "M"} end,
    "conic.scheme: the table does not determine M", "indeterminate")
err(function() conic.scheme{triples = {{"A1", "A2", "A"}}, points = pts, current = {"C", "A3", "X"}, result = "M"} end,
    "the current point's line current[2], current[3] must join two given points", "unknown line")
err(function() conic.scheme{triples = {}, points = pts, current = {"C", "A3", "A4"}, result = "M", extra = 1} end,
    "conic.scheme: unknown option 'extra'", "unknown field")
check.done()
