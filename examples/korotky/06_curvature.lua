-- Curvature along the models of Korotky & Vitovtov against the elastic line
-- kappa(x) of each model through the pins A..E with free ends: the polynomial spline (7)
-- (yellow), the Ferguson lambda-spline of Ex. 1 (magenta), Ferguson (28) (cyan) and the
-- elastic reference (green).  The elastic line has kappa = 0 at its free ends and the least
-- integral of kappa^2; the polynomial is C2 but swings far more; the Ferguson joints are G2
-- (no jumps).  A graph: kappa against x, the two axes at different scales.
local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}
local tg = {1.134, 2.840, 0.985, -1.8154, -2.460}
local models = {
  {korotky.poly_spline(pts), 14, "(7)"},
  {korotky.ferguson_lambda(pts, {TA = tg[1], TE = tg[5], lambda = {1, 2, .5}}), 13, "Ex.1"},
  {korotky.ferguson_tangents(pts, tg), 11, "(28)"},
  {korotky.elastic(pts), 10, "elastic"},
}
window(.8, -2.2, 6, 1.2)
line(P(1, 0), P(5.7, 0), 8)
for i, p in ipairs(pts) do
  line(P(p.x, -2), P(p.x, 1), 8)
  label(({"A", "B", "C", "D", "E"})[i], P(p.x, 1), "n", 7)
end
label("$\\kappa$", P(.82, .55), nil, 7)
label("0", P(1, 0), nil, 8)
for k, m in ipairs(models) do
  local c, col = m[1], m[2]
  -- kappa against x, sampled along the curve's own parameter
  local pts_k = {}
  for i = 0, 400 do
    local t = c.t0 + (c.t1 - c.t0) * i / 400
    pts_k[#pts_k + 1] = P(c(t).x, c:curvature(t))
  end
  path(pts_k, {color = col})
  label(string.format("%s  E = %.4f", m[3], korotky.energy(c)), P(3.05, 1.15 - .2 * k), "e", col)
end
