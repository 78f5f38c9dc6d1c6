-- Conics that know what they are (issue 23): c:conic(), conic.elements and
-- korotky.conic_elements on the engineering-discriminant arcs of (2.97) on A(0,0), B(4,0),
-- C(2,3) (digest konopatsky_ch1_2.md §5.6), Ceva's (2.104), the 90-degree circle of (2.107),
-- five-point conics, weights scaled and negated, and the errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy, err = check.eq, check.near, check.truthy, check.err
local same = check.same_within(1e-12)

local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local function on(e, c)    -- the implicit equation holds along the curve
  local q = e.coef
  for i = 0, 10 do
    local m = c(i / 10)
    if m.w ~= 0 then
      near(q[1] * m.x ^ 2 + q[2] * m.x * m.y + q[3] * m.y ^ 2 + q[4] * m.x + q[5] * m.y + q[6], 0, 1e-12, "on the conic")
    end
  end
end

-- the issue's silent wrong results, each now right
local e3 = conic.ed(A, B, C, 0.3):conic()
eq(e3.kind, "hyperbola", "ED k = 0.3 is a hyperbola")
near(e3.k, 0.3, 1e-15, "its engineering discriminant")
same(e3.center, P(2, 3.675), "its centre, above C")
local e5 = conic.ed(A, B, C, 0.5):conic()
eq(e5.kind, "parabola", "ED k = 0.5 is a parabola")
same(e5.vertex, P(2, 1.5), "vertex K")
same(e5.foci[1], P(2, 1.5 - 2 / 3), "focus 2/3 below the vertex")
same(e5.axes[1], V(0, -1), "the axis points into the parabola")
near(e5.p, 4 / 3, 1e-12, "semi-latus rectum")
eq(e5.center, nil, "a parabola has no centre")
local c7 = conic.ed(A, B, C, 0.7)
local e7 = c7:conic()
eq(e7.kind, "ellipse", "ED k = 0.7 is an ellipse")
same(e7.center, P(2, -0.675), "centre (2, -0.675)")
near(e7.b, 1.575, 1e-12, "vertical semi-axis 0.9 + 0.675")
near(e7.a, 1.575 / math.sqrt(0.50625), 1e-12, "horizontal semi-axis")
near(e7.e, math.sqrt(1 - (e7.b / e7.a) ^ 2), 1e-12, "eccentricity")
near(dist(e7.foci[1], e7.center), math.sqrt(e7.a ^ 2 - e7.b ^ 2), 1e-12, "focal distance")
on(e7, c7)
local k7 = korotky.conic_elements(c7)
same(k7.center, P(2, -0.675), "korotky.conic_elements reads the arc right")
eq(k7.kind, "ellipse", "korotky.conic_elements kind")
eq(korotky.conic_elements(conic.ed(A, B, C, 0.3)).kind, "hyperbola", "korotky: k = 0.3")
eq(korotky.conic_elements(conic.ed(A, B, C, 0.5)).kind, "parabola", "korotky: k = 0.5")
-- the 90-degree ED circle (2.107)
local kc = conic.circle_k(P(1, 0), P(0, 1), P(1, 1))
local ec = conic.ed(P(1, 0), P(0, 1), P(1, 1), kc):conic()
eq(ec.kind, "ellipse", "the circle is an ellipse")
eq(ec.circle, true, "with equal semi-axes")
same(ec.center, P(0, 0), "centred at the origin, not (0.396, 0.396)")
near(ec.a, 1, 1e-12, "radius 1")
near(ec.e, 0, 1e-12, "eccentricity 0")
eq(korotky.conic_elements(conic.ed(P(1, 0), P(0, 1), P(1, 1), kc)).kind, "ellipse", "korotky: the circle")
-- Ceva (2.104): k = 1/4 parabola, 0.09 hyperbola; the conversion to the ED k
eq(conic.ceva(A, B, C, 0.09):conic().kind, "hyperbola", "Ceva k = 0.09 is a hyperbola")
near(conic.ceva(A, B, C, 0.09):conic().k_ceva, 0.09, 1e-12, "its k")
near(conic.ceva(A, B, C, 0.09):conic().k, 0.6 / 1.6, 1e-12, "k_ED = 2 sqrt k/(1 + 2 sqrt k)")
eq(conic.ceva(A, B, C, 0.25):conic().kind, "parabola", "Ceva k = 1/4")
near(e7.k_ceva, (0.7 / 0.6) ^ 2, 1e-12, "k = (k_ED/(2(1 - k_ED)))^2")
-- every weight scaled (by 2, by -1): the same conic
local q = bezier{P(1, 0) * 2, P(1, 1) * (2 * math.sqrt(0.5)), P(0, 1) * 2}
local eq2 = q:conic()
truthy(eq2.circle, "the quarter circle with every weight doubled is a circle")
same(eq2.center, P(0, 0), "centred at the origin, not (1.5, 1.5)")
local neg = bezier{P(0, 0) * -0.7, P(2, 3) * -0.3, P(4, 0) * -0.7}:conic()
same(neg.center, P(2, -0.675), "weights negated: the same ellipse")
near(neg.k, 0.7, 1e-12, "and the same k")
-- five-point conics: the arc of conic.five_points, its closed version and the five points
local F = {P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)}
local ef = conic.elements(F[1], F[2], F[3], F[4], F[5])
eq(ef.kind, "hyperbola", "§2.1.4's five points lie on a hyperbola")
local ea = conic.five_points(F[1], F[2], F[3], F[4], F[5]):conic()
for i = 1, 6 do near(ea.coef[i], ef.coef[i], 1e-12, "the arc's conic is the five points' conic") end
same(ea.center, ef.center, "one centre", 1e-10)
local ew = conic.five_points(F[1], F[2], F[3], F[4], F[5], {whole = true}):conic()
eq(ew.kind, "hyperbola", "the closed conic")
-- coefficients, and a conic not stored as one (the parametrisation by angle)
local ex = conic.elements{1 / 9, 0, 1 / 4, 0, 0, -1}
near(ex.a, 3, 1e-12, "x^2/9 + y^2/4 = 1: a = 3")
near(ex.b, 2, 1e-12, "b = 2")
same(ex.foci[1], P(math.sqrt(5), 0), "focus (sqrt 5, 0)")
near(ex.p, 4 / 3, 1e-12, "p = b^2/a")
eq(ex.k, nil, "no arc, no k")
local ea2 = conic.ellipse{C = P(1, 2), A = P(4, 2), B = P(1, 4)}:conic()
same(ea2.center, P(1, 2), "an angle-parametrised ellipse: centre", 1e-9)
near(ea2.a, 3, 1e-9, "semi-axis 3")
local eh = conic.elements{0, 1, 0, 0, 0, -1}
eq(eh.kind, "hyperbola", "xy = 1")
near(eh.a, math.sqrt(2), 1e-12, "its semi-axis")
near(math.abs(eh.asymptotes[1].x * eh.asymptotes[2].y - eh.asymptotes[1].y * eh.asymptotes[2].x), 1, 1e-12,
     "perpendicular asymptotes")
-- general five conditions: Korotky's C-1 hyperbola from two points with tangents and a third
local r3 = math.sqrt(3)
local g = conic.elements{points = {P(0, 0), P(2, 0), P(1, 1.5)}, tangents = {{P(0, 0), V(1, r3)}, {P(2, 0), V(-1, r3)}}}
eq(g.kind, "hyperbola", "C-1: a hyperbola")
same(g.center, P(1, 1.774519), "its centre (digest B.3)", 1e-6)
near(g.a, 0.274519, 1e-6, "transverse semi-axis")
near(g.b, 0.156586, 1e-6, "conjugate semi-axis")
local ga = korotky.conic_arc(P(0, 0), V(1, r3), P(2, 0), V(-1, r3), P(1, 1.5)):conic()
for i = 1, 6 do near(ga.coef[i], g.coef[i], 1e-12, "the same conic as korotky.conic_arc") end
-- slopes of implicit curves (the textbook's §3.1)
near(plane.conic_slope({1, 0, 1, 0, 0, -1}, P(0.6, 0.8)), -0.75, 1e-15, "circle: -x/y")
eq(plane.conic_slope({1, 0, 1, 0, 0, -1}, P(1, 0)), math.huge, "a vertical tangent")
near(plane.conic_slope(g.coef, P(0, 0)), r3, 1e-9, "the given tangent back")
err(function() plane.conic_slope({1, 0, 1, 0, 0, -1}, P(2, 0)) end, "plane.conic_slope: the point X is not on the curve", "off the curve")
err(function() conic.elements{points = {P(0, 0), P(2, 0)}, tangents = {{P(0, 0), V(1, 1)}}} end,
    "conic.elements: five conditions fix a conic, got 2 points and 1 tangents", "too few")
err(function() conic.elements{points = {P(0, 0), P(0, 0), P(2, 0), P(1, 1), P(3, 3)}} end,
    "conic.elements: the conditions do not fix one conic", "dependent")
-- the conditions are read by the argument layer: its key check, its weight rule, its wording
local g1 = conic.elements{points = {P(0, 0), P(2, 0), P(1, 1.5)},
                          tangents = {{P(0, 0), V(1, r3)}, {P(2, 0) * (1 + 1e-12), V(-1, r3)}}}
near(g1.a, 0.274519, 1e-6, "a tangent's point of weight 1 + 1e-12 is a point")
err(function() conic.elements{points = {P(0, 0)}, tangnts = {}} end,
    "conic.elements: unknown option 'tangnts' (did you mean 'tangents'?)", "a misspelt key")
err(function() conic.elements{points = {P(0, 0)}, tangents = {{P(0, 0), V(1, 1)}, {P(0, 0), P(1, 1)}, 3, 4}} end,
    "conic.elements: argument #1 (tangents) [2] must be {a 2-D point, a 2-D vector}, got table", "a tangent of two points")
err(function() conic.elements{points = {P(0, 0), V(1, 1)}} end,
    "conic.elements: option 'points' [2] must be a 2-D point, got V(1, 1)", "a vector among the points")
err(function() conic.elements{1, 2, 3, "x", 5, 6} end,
    "conic.elements: argument #1 (conic) [4] must be a finite number, got \"x\"", "a string coefficient")
-- errors
err(function() bezier{P(0, 0), P(1, 3), P(2, -3), P(4, 0)}:conic() end,
    "c:conic: the curve does not lie on one conic", "a cubic")
err(function() bezier{P(0, 0, 0), P(1, 1, 1), P(2, 0, 0)}:conic() end,
    "c:conic: the curve is 3-D", "3-D")
err(function() bezier{P(0, 0), P(2, 3) * 0, P(4, 0)}:conic() end,
    "c:conic: the points are a straight line", "middle weight 0")
err(function() conic.elements(P(0, 0), P(1, 1), P(2, 2), P(3, 3), P(0, 5)) end,
    "conic.elements: the five points fix no single conic", "four collinear")
err(function() conic.elements{1, 0, -1, 0, 0, 0} end, "conic.elements: a degenerate conic", "line pair")
err(function() conic.elements{1, 0, 1} end, "conic.elements: argument #1 (conic) must be a list of 6 numbers", "short list")
err(function() conic.elements(P(0, 0), P(1, 1)) end, "conic.elements: argument #3 (C) must be a 2-D point", "two points")
err(function() conic.elements(P(0, 0, 1), P(1, 1), P(2, 2), P(3, 3), P(0, 5)) end,
    "conic.elements: argument #1 (A) must be a 2-D point, got P(0, 0, 1)", "3-D points")
err(function() conic.elements("x") end, "conic.elements: argument #1 (conic) must be", "a string")
check.done()
