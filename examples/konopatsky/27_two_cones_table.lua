-- Konopatsky §2.6 (Table 2.2): the cubics of two cones for the book's five pairs (fP, fQ)
-- The Cartesian simplex of Fig. 2.33 (A = E1, B = E2, C = E3, D = O) with n = -0.5 (the book
-- gives no n; for n outside [0, 1] fP < fQ keeps the cubic inside the tetrahedron): the base
-- arcs APB (red) and AQB (blue) and the cubic (green), one panel per pair.
local A, B, C, D = P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(0, 0, 0)
local pairs_ = {{0.2, 0.5, "hyperbola + parabola"}, {0.5, 0.8, "parabola + ellipse"},
                {0.3, 0.8, "hyperbola + ellipse"}, {0.1, 0.4, "two hyperbolas"}, {0.6, 0.9, "two ellipses"}}
local n = -0.5
for i, pr in ipairs(pairs_) do
  local col, row = (i - 1) % 3, (i - 1) // 3
  view(5 + col * 211, 10 + row * 235, 210 + col * 211, 240 + row * 235)
  camera(map.axonometric(math.rad(35), math.rad(25)))
  window(-0.45, -0.8, 1.25, 1.15)
  for _, e in ipairs{{A, B}, {B, C}, {C, A}, {D, A}, {D, B}, {D, C}} do line(e[1], e[2], 8) end
  conic.ed(A, B, C, pr[1]):draw{color = 12}
  conic.ed(A, B, C, pr[2]):draw{color = 9}
  conic.cones(A, B, C, D, pr[1], pr[2], n):draw{color = 10}
  label("$A$", A, nil, 15) label("$B$", B, nil, 15) label("$C$", C, nil, 15) label("$D$", D, nil, 15)
  camera()
  label(string.format("fP = %.1f  fQ = %.1f", pr[1], pr[2]), P(-0.4, -0.56), "e", 7)
  label(pr[3], P(-0.4, -0.70), "e", 7)   -- 16 px below the line above
end
