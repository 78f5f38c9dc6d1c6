-- Konopatsky §1.3.2 (Fig. 1.7): the O-theorem (1.4) for a pentagon cut by a line d
-- Chosen pentagon A1(0,0), A2(5,-0.5), A3(6.5,3), A4(3,5.5), A5(-0.5,3) and the line d through
-- (-2, 1.5) and (9, 2.6): B_i = A_iA_(i+1) x d (konopatsky.o_theorem), and the product of the
-- ratios (A_iA_(i+1)B_i), the closing factor (A_5A_1B_5) included (the print omits it), is
-- (-1)^5.  The proof's inner point C is joined to the vertices; C_j = CA_j x d.
local A = {P(0, 0), P(5, -0.5), P(6.5, 3), P(3, 5.5), P(-0.5, 3)}
local D1, D2 = P(-2, 1.5), P(9, 2.6)
local prod, ratios, B = konopatsky.o_theorem(A, D1, D2)
local C = P(3, 2.4)
local Cj, pts = {}, {C}
for i = 1, 5 do
  Cj[i] = meet(C, A[i], D1, D2)
  pts[#pts + 1] = A[i]; pts[#pts + 1] = B[i]; pts[#pts + 1] = Cj[i]
end
fit{around = pts, pad = 0.7}
local ends = {lerp(D1, D2, -0.65), lerp(D1, D2, 0.95)}
path({A[1], A[2], A[3], A[4], A[5], A[1]}, {color = 9})
pen{dash = {4, 3}}
for i = 1, 5 do
  local j = i % 5 + 1                                  -- the side line AiA(i+1) out to Bi
  local near = dist(B[i], A[i]) < dist(B[i], A[j]) and A[i] or A[j]
  if dot(B[i] - A[i], B[i] - A[j]) > 0 then line(near, B[i], 8) end
end
pen()
line(ends[1], ends[2], 12)
for i = 1, 5 do
  line(C, A[i], 7)
  if dist(C, Cj[i]) > dist(C, A[i]) then pen{dash = {2, 3}} line(A[i], Cj[i], 7) pen() end
  mark(Cj[i], "open", 5, 7)
  label("$C_" .. i .. "$", Cj[i], nil, 7)
end
for i = 1, 5 do
  mark(A[i], "dot", 5, 15) label("$A_" .. i .. "$", A[i])
  mark(B[i], "dot", 5, 14) label("$B_" .. i .. "$", B[i], nil, 14)
end
mark(C, "dot", 5, 11) label("$C$", C, nil, 11)
label("$d$", ends[2], nil, 12)
caption(string.format("(A1A2B1)(A2A3B2)(A3A4B3)(A4A5B4)(A5A1B5) = %.6f = (-1)^5", prod), "bottom", 7)
