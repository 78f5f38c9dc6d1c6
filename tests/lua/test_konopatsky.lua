-- Konopatsky's curves through Lua (conic, oneratio, interp, approx): the digests' vectors
-- (konopatsky_ch1_2.md, konopatsky_ch3_5.md) through the bindings, the identities (weights sum
-- to 1, curves through their nodes, end tangents, affine invariance, a five-point conic through
-- all five), the book's Runge search, Lua callbacks and their errors, and the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local same = check.same_within(1e-6)
local pi, sqrt = math.pi, math.sqrt

-- every constructor returns the one curve type
local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local ed = conic.ed(A, B, C, 0.3)
eq(getmetatable(ed), getmetatable(bezier{A, B}), "conic.ed is a curve")
same(ed(0.25), P(1.333333, 1.75), "(2.97) k = .3 u = .25")
same(ed(0.5), P(2, 2.1), "(2.97) K on the median")
near(conic.ed_k(A, B, C, P(2, 0.9)), 0.7, 1e-12, "k from K")
same(conic.ed(A, B, C, 0.7)(0.75), P(3.272727, 0.613636), "(2.97) k = .7")
local d0, ca = ed:deriv(0), C - A
near(d0.x * ca.y - d0.y * ca.x, 0, 1e-9, "tangent CA at A")
same(d0, ca * (2 * 0.7 / 0.3), "M'(0) = 2(1 - k)/k (C - A)", 1e-9)
near(conic.circle_k(P(1, 0), P(0, 1), P(1, 1)), 2 - sqrt(2), 1e-14, "(2.107)")
local circ = conic.circle{A = P(1, 0), B = P(0, 1), C = P(1, 1)}
for u = 0, 1, 0.125 do near(dist(circ(u), P(0, 0)), 1, 1e-12, "the ED circle u = " .. u) end

-- Ceva and its k
local cv = conic.ceva(P(0, 0), P(4, 0), P(2, 3), 0.25)
same(cv(2 / 3), P(2, 1.5), "(2.104) t = 2/3 at the median's midpoint")
near(conic.ceva_k(P(0, 0), P(4, 0), P(2, 3), cv(0.4)), 0.25, 1e-12, "(2.100) k")

-- the forms of the ellipse and hyperbola (sets E and H)
local E = {C = P(0, 0), A = P(4, 0), B = P(0, 2)}
local function with(t, extra) local r = {} for k, v in pairs(t) do r[k] = v end
  for k, v in pairs(extra) do r[k] = v end return r end
same(conic.ellipse(E)(pi / 6), P(2.618615, 1.511858), "(2.11)")
same(conic.ellipse(with(E, {by = "radius"}))(3), P(2.581989, 1.527525), "(2.15)")
same(conic.ellipse(with(E, {by = "focal"}))(pi / 2), P(-3.464102, 1), "(2.18)")
same(conic.ellipse(with(E, {by = "compression"}))(pi / 3), P(2, 1.732051), "(2.24)")
same(conic.ellipse(with(E, {by = "conjugate"}))(0.5), P(2.4, 1.6), "(2.32)")
same(conic.ellipse{by = "diameter", K = P(-4, 0), A = P(4, 0), B = P(2, sqrt(3)), lambda = 0.75}(0.5),
     P(-2, 1.732051), "conjugate diameters, variant 2")
local H = {C = P(0, 0), A = P(3, 0), B = P(0, 2)}
same(conic.hyperbola(H)(0.3), P(3.386643, 1.047612), "(2.49)")
same(conic.hyperbola(with(H, {by = "radius", range = {3, 8}}))(4), P(3.721042, 1.467599), "(2.53)")
same(conic.hyperbola(with(H, {by = "focal"}))(2), P(3.235679, 0.808186), "(2.56) corrected branch")
same(conic.hyperbola(with(H, {by = "focal", branch = 2}))(0.3), P(-4.991118, -2.659262), "(2.56) other branch")
local h = conic.hyperbola(H)
for phi = -0.5, 0.5, 0.1 do
  local M = h(phi)
  near(M.x ^ 2 / 9 - M.y ^ 2 / 4, 1, 1e-11, "on the hyperbola")
end
local c, Pt, Qt = conic.tilted(P(0, 0), P(4, 3), P(5, -1), pi / 4, 2, 1)
same(Pt, P(5.282843, 0.979899), "tilted P"); same(Qt, P(5.989949, -1.141421), "tilted Q")
same(c(pi / 4), P(6.011929, -0.241053), "tilted M(pi/4)")
-- Fig. 2.5's auxiliary points: K = CP x AB (beyond B at pi/4), the rotated A (|CA_| = b, and
-- Q = (A_ - C) n/b + C), tau = pi - alpha - theta; theta = 0 makes K the direction of AB
local _, _, _, K, Ar, tau = conic.tilted(P(0, 0), P(4, 3), P(5, -1), pi / 4, 2, 1)
same(K, P(5.76, 4.32), "tilted K"); near(dist(Ar, P(5, -1)), math.sqrt(26), 1e-12, "|C Arot| = b")
same((Ar - P(5, -1)) / math.sqrt(26) + P(5, -1), Qt, "Q from the rotated A")
near(tau, pi - 0.840896668643165 - pi / 4, 1e-12, "tau")
local _, _, _, K0 = conic.tilted(P(0, 0), P(4, 3), P(5, -1), 0, 2, 1)
same(K0, V(0.8, 0.6), "theta = 0: K at infinity")

-- circles, Fig. 2.25
local F = {A = P(0, 0), B = P(0.5, 1), C = P(1, 0)}
local c115 = conic.circle(with(F, {delta = pi / 3}))
same(c115(pi / 3), P(0.5, 0.866025), "(2.115)")
same(conic.circle(with(F, {R = 0.5}))(pi), P(1.5, 0), "(2.118)")

-- the five-point conic passes through all five, at its parameters
local pts = {P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)}
local c5, u = conic.five_points(table.unpack(pts))
for i, name in ipairs{"A", "B", "C", "D", "E"} do same(c5(u[name]), pts[i], "five points: " .. name, 1e-12) end
near(u.B, 1.75, 1e-12, "corrected u_B")
same(c5(0.5), P(0.531496, 0.094488), "M(0.5)")
-- affine invariance: the conic of the images is the image of the conic
local f = affine({P(0, 0), P(1, 0), P(0, 1)}, {P(2, 1), P(5, 2), P(1, 4)})
local img = {}
for i, p in ipairs(pts) do img[i] = f(p) end
local c5f = conic.five_points(table.unpack(img))
for _, t in ipairs{0.2, 0.6, 1.3, 2.2} do same(c5f(t), f(c5(t)), "affine invariance t = " .. t, 1e-9) end

same(conic.five_points2{C = P(0.5, 1), A = P(0, 0), B = P(1, 0), p1 = .7, p2 = .7, q2 = .8, q3 = .8}(0.5),
     P(0.438017, 0.413223), "Fig. 2.17")
same(conic.redundant(P(0, 0), P(1, 0), P(0, 1), 0.25, 0.25), P(0.692308, 0.076923), "(2.120)")
same(conic.redundant(P(0, 0), P(1, 0), P(0, 1))(0.75), P(0.076923, 0.692308), "(2.121)")
same(conic.reparam{C = P(0, 0), A = P(4, 0), B = P(1, 3)}(math.atan(3) / 2), P(1.166280, 0.840607), "§2.4.1")
same(conic.sinusoid{C = P(0, 0), A = P(1, 0), B = P(0, 1), k = {6, 24}}(pi / 6), P(0.751758, 0.434028), "(2.144)")
same(conic.cycloid{C = P(0, 0), A = P(0, 2), B = P(pi, 0)}(pi / 2), P(2.570796, 1), "convex cycloid")
same(conic.cycloid{C = P(0, 0), A = P(0, 2), B = P(pi, 0), concave = true}(pi / 2), P(0.570796, 1), "concave")
same(conic.cones(P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(0, 0, 0), .8, .3, .5)(0.5),
     P(0.286654, 0.286654, 0.143327), "§2.6")
local arc = conic.contour(P(0, 0), P(4, 0), P(2, 4), function(t) return t end, function(t) return t * t end)
same(arc(0.5), P(1.5, 2.333333), "(2.161)")
same(arc(0), P(0, 0), "(2.161) limit at A1")
local tr = conic.triples(P(3, 0.2), P(1.2, 0.9), P(2, 1.8), P(0.2, 1.3), P(0.5, 2.7))
same(tr(0), P(3, 0.2), "triples (b) through A1")

-- chapter 3
local A3, B3, C3, D3 = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0), P(4, 3, 2)
same(oneratio(A3, B3, C3)(0.3), P(1.41, 0.63, 0), "(3.1)")
same(oneratio.tetra(A3, B3, C3, D3)(0.3), P(1.41, 1.26, 0.42), "(3.2)")
same(oneratio.tetra(A3, B3, C3, D3)(0.5), (A3 + B3 + C3 + D3) / 4, "(3.2) centroid")
same(oneratio.bezier3(A3, C3, D3, B3)(0.5), A3 / 8 + C3 * 3 / 8 + D3 * 3 / 8 + B3 / 8, "(3.4)")
same(oneratio.smooth(A3, B3, C3, 3)(0.3), P(0.6279310345, 1.716206897, 0), "M_3")
near(oneratio.smooth(A3, B3, C3, 3):curvature(0), 0, 1e-9, "M_3 straightens at A")
same(oneratio.desargues(A3, B3, C3, D3)(0.3), P(0.874137931, 0.9, 0.09310344828), "(3.6)")
same(oneratio.closed(A3, B3, C3, 0.8, 0.5, 2)(0.3), P(2.365218978, 0.7628978102, 0), "closed scheme 2")
local dc = oneratio.double_contact(P(0, 0), P(10, 0), P(4, 6), 0.3, 0.7, function(v) return v * v end)
same(dc(0), P(0, 0), "double contact M(0) = A"); same(dc(1), P(10, 0), "M(1) = B")
local dcc = oneratio.double_contact(P(0, 0), P(10, 0), P(4, 6), 0.3, 0.7, 0.5)
same(dcc(0.5), (conic.ed(P(0, 0), P(10, 0), P(4, 6), .3)(.5) + conic.ed(P(0, 0), P(10, 0), P(4, 6), .7)(.5)) / 2,
     "a constant blend")

-- chapter 4: weights sum to 1, curves through their nodes, the book's numbers
local w = interp.weights(3, 0.3)                      -- the book's order 3: four nodes
near(w[1], 77 / 2000, 1e-15, "(4.16) weight 1"); near(w[2], 2079 / 2000, 1e-15, "weight 2")
local s = 0 for _, x in ipairs(interp.weights({0, 0.2, 0.7, 1}, 0.44)) do s = s + x end
near(s, 1, 1e-14, "weights sum to 1")
local nodes = {P(0, 0), P(1, 3), P(2, 1), P(3, 4), P(4, 1), P(5, 5), P(6, 9)}
local L6 = interp.lagrange(nodes)
for j = 0, 6 do same(L6(j / 6), nodes[j + 1], "order 6 through node " .. j, 1e-12) end
same(L6(0.3), P(1.8, 33729 / 78125), "the exact TV of order 6", 1e-12)
local cps = interp.controls({P(0.3), P(-1.2), P(2.5)})
near(cps[2].x, -0.5 * 0.3 + 2 * -1.2 - 0.5 * 2.5, 1e-13, "(4.9)")
same(interp.conic(P(0, 0, 0), P(2, 2, 0), P(4, 0, 0), 0.7)(0.3), P(18 / 19, 30 / 19, 0), "§4.1")
local a4 = interp.arc({P(0, 0), P(3, 2), P(6, 2), P(9, 0)}, P(0, 2), P(9, 2))
same(a4(1 / 3), P(3, 2), "§4.9 through M2"); same(a4:deriv(0), V(0, 10), "M'(0) = 5(C2 - M1)")
local v = interp.adaptive({P(8.89, 5), P(1.11, 7), P(0.33, 8)})
near(v[2], 0.908878504672897, 1e-14, "§4.10 v")
same(interp.prototype("trig", {P(1, 0), P(0, 1), P(-1, 0)}, 0, 2 * pi)(3 * pi / 2), P(0, -1), "(4.40) whole ellipse")
same(interp.prototype("desargues", {P(0, 0), P(1, 2), P(3, 2), P(4, 0)})(1 / 3), P(1, 2), "(4.35)")
local ex = interp.prototype("exp", {P(0, 0), P(1, 2), P(2, 0)}, {0.5, -1, 2})
same(ex(0.5), P(1, 2), "(4.39) through the middle node")
local bz = interp.basis({function(t) return 1 end, function(t) return t end, function(t) return t * t end},
                        {P(0, 0), P(1, 1), P(2, 0)}, {0, 0.5, 1})
same(bz(0.25), L6 and interp.lagrange({P(0, 0), P(1, 1), P(2, 0)})(0.25), "basis engine = Lagrange on the power basis")
local r22, co = interp.rational22({P(1, 2), P(2, 1), P(4, 1), P(6, 3), P(7, 6)})
near(co[1][1], 16 / 3, 1e-10, "(4.38) x numerator t^2")
same(r22(0.6), P((16 * .36 + 1.2 + 3) / (4 * .36 - 2.4 + 3), (136 * .36 - 112 * .6 + 30) / (16 * .36 - 13.2 + 15)), "(4.38)")

-- chapter 5: the Runge search
local runge = function(x) return 1 / (1 + 25 * x * x) end
local xs, mse, evals = approx.optimal_nodes(runge, -1, 1, 6)
near(mse, 2.83922e-5, 2.83922e-5 * 1e-6, "Runge MSE")
near(xs[2], -0.233198, 2e-6, "node 2"); near(xs[3], -0.06054, 2e-6, "node 3")
truthy(evals > 100, "evaluations counted")
near(approx.mse(runge, {-1, -0.233198, -0.06054, 0.06054, 0.233198, 1}), 2.839222e-5, 2e-10, "book nodes")
near(approx.lagrange_mse(runge, approx.chebyshev(23), -1, 1), 2.53e-5, 0.005e-5, "Chebyshev 23 (book 0.0000253)")
local ac = approx.curve(runge, xs)
same(ac(0.2), P(xs[2], runge(xs[2])), "the curve through its second node", 1e-12)
local xm, fm = approx.nelder_mead(function(x, y) return (x - 1) ^ 2 + 10 * (y + 2) ^ 2 end, {0, 0})
near(xm[1], 1, 1e-5, "nelder_mead x"); near(xm[2], -2, 1e-5, "nelder_mead y")
err(function() approx.nelder_mead(function(x, y) end, {0, 0}) end,
    "approx.nelder_mead: the function must return a number, got nil", "a function returning nothing")
err(function() interp.basis({function(t) return 1 end, function(t) return "t" end}, {P(0, 0), P(1, 1)}, {0, 1}) end,
    "interp.basis: the basis function [2] must return a number, got string", "a basis function returning a string")

-- Lua errors inside callbacks surface at the user's line; argument errors in house style
err(function() return oneratio.double_contact(A, B, C, .3, .7, function() error("boom") end)(0.3) end,
    "boom", "an error in the blend")
err(function() approx.mse(function() error("bad f") end, {-1, 0, 1}) end, "bad f", "an error in f")
err(function() conic.ed(A, B, 3, 0.5) end, "conic.ed: argument #3 (C) must be a point, got 3", "a number for C")
err(function() conic.ed(A, B, C, 0) end, "conic.ed: argument #4 (k) must be a non-zero number", "k = 0")
err(function() conic.ed(A, B, P(1, 2, 3), 0.5) end, "conic.ed: argument #3 (C) is 3-D, but argument #1 (A) is 2-D (mixed dimensions)", "dims")
err(function() conic.ed(A, B, C * 2, 0.5) end, "membership condition", "a weighted point")
err(function() conic.ed_k(A, B, C, P(3, 1)) end, "must lie on the median", "K off the median")
err(function() conic.ellipse{C = P(0, 0), A = P(4, 0)} end, "conic.ellipse: option 'B' must be a point, got nil", "field")
err(function() conic.ellipse{C = P(0, 0), A = P(4, 0), B = P(0, 2), by = "round"} end, "conic.ellipse: option 'by' must be \"angle\", \"radius\"", "by")
err(function() conic.ellipse{C = P(0, 0), A = P(2, 0), B = P(0, 2), by = "radius"} end,
    "outside the form's conditions", "a = b radial")
err(function() conic.ellipse{C = P(0, 0), A = P(4, 0), B = P(0, 2), by = "radius", range = {1, 3}} end,
    "conic.ellipse: option 'range' must lie within the form's real range [2, 4]", "range")
err(function() conic.five_points(P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.5, 0.5)) end,
    "no three of them collinear", "collinear five")
err(function() conic.cones(A, B, C, P(1, 1), .3, .8, 2) end, "must be 3-D or more", "cones in 2-D")
err(function() oneratio.double_contact(A, B, C, .4, .4) end, "(kq) must be different from kp", "kp = kq")
err(function() oneratio.smooth(A, B, C, 0) end, "oneratio.smooth: argument #4 (n) must be an integer from 1 to 40, got 0", "n")
err(function() interp.lagrange({P(0, 0), P(1, 1)}, {0.5, 0.5}) end, "must be distinct", "params")
err(function() interp.adaptive({P(0, 0), P(2, 0), P(1, 0)}) end, "order of the nodes", "adaptive order")
err(function() interp.prototype("spline", {}) end, "argument #1 (kind) must be \"desargues\"", "kind")
err(function() interp.prototype("exp", {P(0, 0), P(1, 2), P(2, 0)}, {1, 1, 2}) end, "exponents must be distinct", "k")
err(function() approx.optimal_nodes(runge, 1, -1, 6) end, "argument #3 (b) must be greater than a", "a > b")
err(function() approx.optimal_nodes(runge, -1, 1, 2) end, "approx.optimal_nodes: argument #4 (N) must be an integer from 3 to 16, got 2", "N")
-- five points where ED is parallel to CA (D's u is infinite): the range is the other points'
local function ell(a) return P(2 * math.cos(a), 1.2 * math.sin(a)) end
local c5e, ue = conic.five_points(ell(0.5), ell(3.0), ell(5.0), ell(1.5), ell(4.0))
truthy(math.abs(ue.D) > 1e6, "u_D at infinity")
local lo, hi = c5e.t0, c5e.t1
truthy(hi - lo < 10, "a bounded range")
for t = lo, hi, (hi - lo) / 8 do
  local M = c5e(t)
  near(M.x ^ 2 / 4 + M.y ^ 2 / 1.44, 1, 1e-9, "on the ellipse, t = " .. t)
end

check.done()
