-- Konopatsky §2.1.1.1 (Table 2.1): the tilted ellipse for theta = 0, pi/4, pi/2
-- Triangle ABC (blue) with A(0,0), B(4,3), C(5,-1); the ellipse of centre C with semi-axes
-- m = 2 and n = 1 whose major axis CP makes the angle theta with line AB; the semi-axes CP, CQ
-- in green.  Three panels (2 x 2 grid, equal units), theta = 0, pi/4, pi/2.
local A, B, C = P(0, 0), P(4, 3), P(5, -1)
for i, th in ipairs{0, math.pi / 4, math.pi / 2} do
  local col, row = (i - 1) % 2, (i - 1) // 2
  view(col * 320 + 2, row * 240 + 2, col * 320 + 318, row * 240 + 238)
  window(-0.4, -3.3, 8.4, 3.3)            -- 8.8 x 6.6 units on 316 x 236 px
  path({A, B, C, A}, {color = 9})
  local e, Pa, Qa = conic.tilted(A, B, C, th, 2, 1)
  e:draw{color = 15}
  line(C, Pa, 10) line(C, Qa, 10)
  label("$A$", A, nil, 9) label("$B$", B, nil, 9) label("$C$", C, nil, 9)
  label("$P$", Pa, nil, 10) label("$Q$", Qa, nil, 10)
  label(({"$\\theta = 0$", "$\\theta = \\pi/4$", "$\\theta = \\pi/2$"})[i], P(-0.3, -3.0), "e", 7)
end
