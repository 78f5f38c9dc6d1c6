-- Cubic splines with four kinds of ends, by uniform and by chord-length parameters
-- Buimov §4.2: the C2 spline through the points by the book's tridiagonal system of the
-- joints. The book has clamped ends only (given end tangents, red arrows); natural (P'' = 0),
-- cyclic (P' and P'' equal at both ends) and anticyclic (opposite) ends are Rogers & Adams'.
-- Top row: the uniform ("normalised") parameter t_k = 1; bottom row: chord lengths, which
-- follow unevenly spaced points more closely. The grey polygon joins the points.
local pts = {P(0, 0), P(0.6, 1.6), P(1.2, 1.8), P(3.2, 0.8), P(3.6, -0.6), P(2.4, -1.2), P(0, 0)}
local ends = {"clamped", "natural", "cyclic", "anticyclic"}
local d0, d1 = V(0, 2.5), V(-2.5, 1.2)

for row, param in ipairs{"uniform", "chord"} do
  for col, e in ipairs(ends) do
    local F = affine.frame(P(36 + 152 * (col - 1), 118 + 225 * (row - 1)), V(36, 0), V(0, -36))
    for i = 1, #pts - 1 do line(F(pts[i]), F(pts[i + 1]), 8) end
    local s, tg = buimov.spline(pts, {ends = e, d0 = d0, d1 = d1, param = param})
    s:draw{color = 14, map = F}
    for _, p in ipairs(pts) do circle(F(p), 2, 15) end
    if e == "clamped" then
      line(F(pts[1]), F(pts[1] + d0 * 0.3), 12); line(F(pts[#pts]), F(pts[#pts] + d1 * 0.3), 12)
      label("$P'_1$", F(pts[1] + d0 * 0.3), nil, 12)
      label("$P'_n$", F(pts[#pts] + d1 * 0.3), nil, 12)
    else   -- the end tangents the condition produced
      line(F(pts[1]), F(pts[1] + tg[1] * 0.3), 10)
      line(F(pts[#pts]), F(pts[#pts] + tg[#pts] * 0.3), 13)
    end
    label(e, F(P(1.8, 2.6)), "c", 15)
  end
  label(param == "uniform" and "uniform parameter, t_k = 1" or "chord length, t_k = |P_k - P_k-1|",
        P(320, 225 * row - 10), "c", 7)
end
