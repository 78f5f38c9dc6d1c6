-- Konopatsky §1.2.2 (Fig. 1.2): the surface of a moving simplex on three guide lines
-- The digest's recipe with chosen points (the book prints none): the tetrahedron DABC,
-- D(0,0,0), A(4,0,0), B(0,5,0), C(0,0,3), and the guides' ends A'(3.5,5,0.8), C'(0.5,5,3.5):
-- N_A = (A' - A)phi(u) + A with phi = u^2, N_B = (B - D)u + D, N_C = (C' - C)f(u) + C with
-- f = sin(pi u/2).  The generator in the moving simplex N_A N_B N_C is
-- M = (N_A - N_C)p(v) + (N_B - N_C)q(v) + N_C with p = (1 - v)^2, q = v^2 (a parabola); the
-- triangles N_A N_B N_C at u = 0, 1/2, 1 (yellow) and the swept patch (green grid).
local D, A, B, C = P(0, 0, 0), P(4, 0, 0), P(0, 5, 0), P(0, 0, 3)
local A1, C1 = P(3.5, 5, 0.8), P(0.5, 5, 3.5)
local NA = curve(function(u) return (A1 - A) * u ^ 2 + A end, 0, 1)
local NB = curve(function(u) return (B - D) * u + D end, 0, 1)
local NC = curve(function(u) return (C1 - C) * math.sin(math.pi * u / 2) + C end, 0, 1)
local gen = curve(function(v) return P((1 - v) ^ 2, v ^ 2) end, 0, 1)
local s = konopatsky.moving_simplex(NA, NB, NC, gen)
local view = map.view{azimuth = -40, elevation = 22}
camera(view)
fit{around = {D, A, B, C, A1, C1}, pad = 0.4}
for _, e in ipairs{{D, A}, {D, B}, {D, C}, {A, B}, {B, C}, {C, A}} do line(e[1], e[2], 8) end
s:wireframe{nu = 8, nv = 8, color = 2}
NA:draw{color = 12} NB:draw{color = 12} NC:draw{color = 12}
for _, u in ipairs{0, 0.5, 1} do
  local a, b, c = NA(u), NB(u), NC(u)
  line(a, b, 14) line(b, c, 14) line(c, a, 14)
  s:iso("u", u):draw{color = 10}
end
for _, p in ipairs{D, A, B, C, A1, C1} do mark(p, "dot", 5, 15) end
local h = 0.5
for _, p in ipairs{NA(h), NB(h), NC(h)} do mark(p, "dot", 4, 14) end
label("$D$", D) label("$A$", A) label("$B$", B) label("$C$", C)
label("$A'$", A1) label("$C'$", C1)
label("$N_A$", NA(h), nil, 14) label("$N_B$", NB(h), nil, 14) label("$N_C$", NC(h), nil, 14)
label("$M$", s(h, 0.5), nil, 10)
mark(s(h, 0.5), "dot", 4, 10)
camera()
