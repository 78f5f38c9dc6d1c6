-- Example 7 — Smoothstep from two power pieces ("half-splines") of degree n
-- The unit square (white box, scale 400, origin at its lower-left corner (120, 440), y up) and
-- four white S-curves (thick dots) g for n = 2, 4, 6, 8: g(t) = 2^(n-1) t^n for t < 1/2 and its
-- point reflection 1 - 2^(n-1) (1 - t)^n after (§H block 4, `smooth.power`). All satisfy
-- g(0) = 0, g(1) = 1, g'(0) = g'(1) = 0, pass through the centre and steepen as n grows.
-- The article's c = 2^(n-1) follows from g(1/2) = 1/2 (the OCR prints it as "2n-1").
-- QBasic's `for t = 0 to 1 step .0001` runs 10000 times (never reaching t = 1): qb = true.

screen(12)
local square = screenmap(120, 440, 400)          -- the unit square onto the screen, y up
line(P(square(0, 0)), P(square(1, 1)), nil, "b")

for n = 2, 8, 2 do
  local g = smooth.power(n)
  plot(function(t) return t, g(t) end, {t = {0, 1, .0001}, qb = true, brush = "dot", map = square})
end
