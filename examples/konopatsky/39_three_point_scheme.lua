-- Konopatsky §4.10 (Fig. 4.6 a, b): the scheme of the three-point interpolation curve
-- The quadratic (4.31) through M1 = A, M2, M3 = B at v = 0, 1/2, 1 is the Bezier curve A, C, B
-- with C = -M1/2 + 2M2 - M3/2, so the line CM2 halves the chord AB at T.  N divides AB as M2
-- divides the data along x (AN/AB = v2 of §4.10).  (a) Evenly spaced data (chosen): N = T and
-- the arc is calm.  (b) Uneven data (the book's Fig. 4.7 nodes x = 8.89, 1.11, 0.33;
-- y = 5, 7, 8): AN >> NB, yet the curve still puts M2 over T, so it swings back (an oscillation).
local function pt(p, name, c) mark(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end
local cases = {{P(0, 0), P(4.5, 3), P(9, 0)}, {P(8.89, 5), P(1.11, 7), P(0.33, 8)}}
local wins = {{-1.5, -2.5, 10.5, 6.5}, {-2.5, 2, 10, 11.5}}
for i, M in ipairs(cases) do
  view(5 + (i - 1) * 315, 60, 310 + (i - 1) * 315, 420)
  window(table.unpack(wins[i]))
  local ctrl = interp.controls(M)
  local Cc = ctrl[2]
  local T = mid(M[1], M[3])
  local v = interp.adaptive(M)
  local N = lerp(M[1], M[3], v[2])
  path(ctrl, {color = 8}) line(M[1], M[3], 8)
  pen{dash = {4, 3}} line(Cc, T, 7) pen()
  interp.lagrange(M):draw{color = 10}
  pt(M[1], "$M_1 = A$") pt(M[2], "$M_2$") pt(M[3], "$M_3 = B$") pt(Cc, "$C$", 7)
  if dist(N, T) < 1e-9 then pt(T, "$N \\equiv T$", 14)     -- (a): one point, one label
  else pt(N, "$N$", 14) pt(T, "$T$", 7) end
  label(string.format("(%s) AN/AB = %.3f", i == 1 and "a" or "b", v[2]),
        P(wins[i][1] + 0.2, wins[i][2] + 0.5), "e", 7)
end
