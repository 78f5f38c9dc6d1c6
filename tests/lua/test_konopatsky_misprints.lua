-- Konopatsky: the printed formulas that are wrong (digest konopatsky_ch1_2.md §9, the checks of
-- konopatsky_ch1_2_verify.py) shown failing beside the corrected ones the library implements,
-- and the printed results of chapter 5 (konopatsky_ch3_5.md §3.3-3.4): Runge's polynomials
-- from the optimal nodes, and the C4-spline example, whose printed curve is of order 6 through
-- 7 nodes at t = j/6, not the order-5 curve (4.25) the text names.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local near, truthy = check.near, check.truthy
local same = check.same_within(1e-6)
local sin, cos, sqrt, acos, pi = math.sin, math.cos, math.sqrt, math.acos, math.pi

-- (2.16) the focal angle of the ellipse: the printed first term lacks the factor p -------------
-- (p = b^2/a = 1 for the digest's set E, so the check takes a = 5, b = 3: p = 1.8)
local a, b = 5, 3
local c = sqrt(a * a - b * b)
local e, p = c / a, b * b / a
local A, B, F2 = P(a, 0), P(0, b), P(-c, 0)
local focal = conic.ellipse{C = P(0, 0), A = A, B = B, by = "focal"}   -- (2.18) at F2
local function on_ellipse(M) return M.x ^ 2 / a ^ 2 + M.y ^ 2 / b ^ 2 - 1 end
for _, phi in ipairs{pi / 3, pi / 2, 4.0} do
  local den = 1 - e * cos(phi)
  local q = p * sin(phi) / (den * b)
  local with_p = (A - F2) * (p * a * sin(acos(e) - phi) / (den * (a * b + c * b))) + (B - F2) * q + F2
  local printed = (A - F2) * (a * sin(acos(e) - phi) / (den * (a * b + c * b))) + (B - F2) * q + F2
  near(on_ellipse(with_p), 0, 1e-12, "(2.16) with the factor p is on the ellipse, phi = " .. phi)
  same(with_p, focal(phi), "(2.16) corrected = conic.ellipse{by = \"focal\"}", 1e-12)
  truthy(math.abs(on_ellipse(printed)) > 1e-3, "(2.16) as printed is off the ellipse, phi = " .. phi)
end

-- (2.55) the focal angle of the hyperbola at F1 (set H): the printed signs put M off the curve --
a, b = 3, 2
c = sqrt(a * a + b * b)
e = c / a
A, B = P(a, 0), P(0, b)
local F1 = P(c, 0)
local function on_hyperbola(M) return M.x ^ 2 / a ^ 2 - M.y ^ 2 / b ^ 2 - 1 end
local H = {C = P(0, 0), A = A, B = B, by = "focal"}
local branch1 = conic.hyperbola(H)
H.branch = 2
local branch2 = conic.hyperbola(H)
for _, case in ipairs{{0.3, branch2}, {2.0, branch1}, {5.0, branch1}} do
  local phi, arc = case[1], case[2]
  local den = 1 - e * cos(phi)
  local q = b * sin(phi) / (a * den)
  local fixed = (A - F1) * (b * (b * cos(phi) + c * sin(phi)) / (a * den * (a - c))) + (B - F1) * q + F1
  local printed = (A - F1) * (b * (b * cos(phi) - c * sin(phi)) / (a * den * (c - a))) + (B - F1) * q + F1
  near(on_hyperbola(fixed), 0, 1e-11, "(2.55) corrected is on the hyperbola, phi = " .. phi)
  same(fixed, arc(phi), "(2.55) corrected = (2.56) conic.hyperbola{by = \"focal\"}", 1e-9)
  truthy(math.abs(on_hyperbola(printed)) > 1e-3, "(2.55) as printed is off the hyperbola, phi = " .. phi)
end

-- the printed (2.74): the conic "through five points" of §2.1.4 built on the wrong S (2.68) ---
local pD, qD, pE, qE = 0.3, 0.8, 0.7, 0.6
local Cn, An, Bn = P(0, 0), P(1, 0), P(0, 1)
local Dn, En = P(pD, qD), P(pE, qE)
local function printed74(u)
  local den = qD * (pE - pD) * u + (pD - 1) * (pE * qD - pD * qE)
  return (An - Cn) * (qD * (pD - pE) * u * (u - 1) / den + u)
       + (Bn - Cn) * (qE * qD * (pD - pE) * u * (u - 1) / ((pE - u) * den)) + Cn
end
local uB_printed = pE * (1 - pD) / (pE * qD - pD - qD + 1)
same(printed74(uB_printed), P(63 / 82, 20 / 41), "the printed (2.74) at its own u_B", 1e-12)
truthy(dist(printed74(uB_printed), Bn) > 0.5, "the printed (2.74) misses B")
same(printed74(0.5), P(-0.254717, -2.264151), "the printed (2.74) at u = 0.5")
local uD = (pE * qD - pD * qE) / (qD - qE)
same(printed74(uD), Dn, "the printed (2.74) does pass D", 1e-12)
same(printed74(1), An, "and A", 1e-12)
-- the printed S is the meet of AD with the parallel to CB through E, not BE x AD
local S_printed = P(pE, qD * (pE - 1) / (pD - 1))
same(S_printed, (meet(An, Dn, En, En + (Bn - Cn))), "the printed S (2.68) = AD x (E + t CB)", 1e-12)
same((meet(Bn, En, An, Dn)), P(0.25, 0.857143), "the corrected S = BE x AD")
local c5, u = conic.five_points(An, Bn, Cn, Dn, En)
near(u.B, pE / (1 - qE), 1e-12, "the corrected u_B = pE/(1 - qE)")
same(c5(u.B), Bn, "the corrected conic passes B", 1e-12)
same(c5(u.E), En, "and E", 1e-12)
same(c5(0.5), P(0.531496, 0.094488), "the corrected M(0.5)")

-- Runge's function, 6 optimal nodes (§5.2): the printed monomial coefficients of x(t), y(t) ----
local runge = function(x) return 1 / (1 + 25 * x * x) end
local nodes = {-1, -0.233198, -0.06054, 0.06054, 0.233198, 1}
local ctrl = interp.controls((function()
  local pts = {}
  for j, x in ipairs(nodes) do pts[j] = P(x, runge(x)) end
  return pts
end)())
-- Bernstein to power basis: a_k = binom(n, k) sum_i (-1)^(k - i) binom(k, i) C_i
local function binom(n, k)
  local r = 1
  for i = 1, k do r = r * (n - i + 1) / i end
  return r
end
local function monomial(axis)
  local n, co = #ctrl - 1, {}
  for k = 0, n do
    local s = 0
    for i = 0, k do s = s + (-1) ^ (k - i) * binom(k, i) * ctrl[i + 1][axis] end
    co[k + 1] = binom(n, k) * s
  end
  return co
end
local bx = {-1, 7.652, -28.398, 57.076, -57.215, 22.886}          -- the book, t^0 .. t^5
local by = {0.038, -0.088, 15.691, -31.206, 15.603, -9.964e-9}
local cx, cy = monomial(1), monomial(2)
for k = 1, 6 do
  near(cx[k], bx[k], 1.5e-3, "Runge x(t): the printed t^" .. (k - 1) .. " coefficient")
  near(cy[k], by[k], 1.5e-3, "Runge y(t): the printed t^" .. (k - 1) .. " coefficient")
end
near(cy[6], 0, 1e-9, "y's t^5 term vanishes by symmetry (the print's -9.964e-9 is round-off)")
near(approx.mse(runge, nodes), 2.83922e-5, 1e-10, "MSE of the book's nodes, m = 100, /(m + 1)")

-- the C4 spline example (§5.3, example 3): the printed x(t), y(t) ------------------------------
local function xs(t) return -320.19785 * t * (t - 1.383019) * (t * t - 0.05275 * t + 0.34039) * (t * t - 1.83595 * t + 1.22856) end
local function ys(t)
  return -450355.86111 * t * (t - 0.14499) * (t - 0.51387) * (t - 1.11087) * (t * t - 1.72689 * t + 0.74554)
end
local listed = {0, 22.169644, 35.376097, 44.698286, 51.476, 57.123197, 62}  -- x1 = 0, x7 = 62 (A1, A6)
for j = 0, 6 do
  near(xs(j / 6), listed[j + 1], 5e-4, "C4 spline: x(" .. j .. "/6) is the listed node")
end
truthy(math.abs(xs(1 / 5) - listed[2]) > 3, "at t = j/5 (the order-5 curve the text names) it is not")
local ordinates = {0, -258.963, -1115.347, -89.470, 411.668, 20.830, 387.055}   -- digest §3.4
local pts = {}
for j = 0, 6 do
  near(ys(j / 6), ordinates[j + 1], 1e-3, "C4 spline: y(" .. j .. "/6)")
  pts[j + 1] = P(xs(j / 6), ys(j / 6))
end
-- degree 6 in both coordinates: the order-6 interpolation curve (4.28) through those 7 nodes
local order6 = interp.lagrange(pts)
for _, t in ipairs{0.05, 0.3, 0.55, 0.9} do
  same(order6(t), P(xs(t), ys(t)), "C4 spline: the printed curve is the order-6 curve (4.28), t = " .. t, 1e-6)
end
near(xs(1), 62, 5e-4, "it ends at A6's x = 62")
near(ys(1), 387, 0.06, "and y = 387 to the rounding of the printed coefficients")

check.done()
