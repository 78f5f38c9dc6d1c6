-- Example 8 — Asymmetric junction of half-splines of degrees n and m at t0
-- Smoothsteps joined from c1 t^n (t < t0) and 1 - c2 (1 - t)^m (t >= t0) at an arbitrary t0,
--   c1 = m/((n - n t0 + m t0) t0^(n-1)),  c2 = (1 - c1 t0^n)/(1 - t0)^m
-- (§H block 5, `smooth.half`), here n = 8, m = 2, for t0 = .1, .3, .5, .7, .9: five white curves
-- (thick dots) in the unit square (scale 400, origin (120, 440), y up), each with its junction
-- point (t0, v) marked by a circle of radius 5. The thin white curve (one pixel per sample) is
-- the locus of the junction points, v(t0) = m t0/(n - n t0 + m t0) (`smooth.locus`), which the
-- article proves continuous and increasing, so a junction exists for every n, m, t0.
-- Colour 0: the listing draws the unit square in colour 0, the background, so it is invisible;
-- kept as printed. QBasic loop counts (qb = true): 1001 locus samples, 10000 per curve.

screen(12)
local square = screenmap(120, 440, 400)
local n, m = 8, 2
line(P(square(0, 0)), P(square(1, 1)), 0, "b")  -- colour 0: invisible, as in the listing

plot(function(t0) return t0, smooth.locus(n, m, t0) end, {t = {0, 1, .001}, qb = true, map = square})

for t0 = .1, .91, .2 do
  local g = smooth.half(n, m, t0)
  circle(P(square(t0, g.v)), 5)                   -- the junction point, on the locus
  plot(function(t) return t, g(t) end, {t = {0, 1, .0001}, qb = true, brush = "dot", map = square})
end
