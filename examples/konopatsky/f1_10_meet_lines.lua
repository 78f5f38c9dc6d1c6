-- Konopatsky §1.3.5 (Fig. 1.10): the meet of two lines by the S-theorem, (1.5)
-- Chosen simplex C(0,0), A(6,0), B(1,5) and A_i = (A - C)p_i + (B - C)q_i + C with (p_i, q_i) =
-- (0.1, 0.2), (0.8, 0.6), (0.7, 0.05), (0.15, 0.75).  The current point M = (A2 - A1)lambda + A1
-- of line A1A2 (here lambda = 0.35) and the triangle MA3A4 (hatched); K is where that area
-- is zero, lambda of (1.5) against meet(A1, A2, A3, A4).
local C, A, B = P(0, 0), P(6, 0), P(1, 5)
local pq = {{0.1, 0.2}, {0.8, 0.6}, {0.7, 0.05}, {0.15, 0.75}}
local Ai = {}
for i, v in ipairs(pq) do Ai[i] = (A - C) * v[1] + (B - C) * v[2] + C end
local p1, q1, p2, q2 = pq[1][1], pq[1][2], pq[2][1], pq[2][2]
local p3, q3, p4, q4 = pq[3][1], pq[3][2], pq[4][1], pq[4][2]
local p21, q21, p34, q34 = p2 - p1, q2 - q1, p3 - p4, q3 - q4
local lam = (q3 * p4 - p3 * q4 - p1 * q34 + q1 * p34) / (p21 * q34 - q21 * p34)   -- (1.5)
local K = meet(Ai[1], Ai[2], Ai[3], Ai[4])
local M = (Ai[2] - Ai[1]) * 0.35 + Ai[1]
fit{around = {C, A, B}, pad = 0.6}
hatch({M, Ai[3], Ai[4]}, 6, -45, 6)
path({C, A, B, C}, {color = 9})
line(Ai[1], Ai[2], 15) line(Ai[3], Ai[4], 15)
path({M, Ai[3], Ai[4], M}, {color = 6})
for _, p in ipairs{C, A, B} do mark(p, "dot", 5, 9) end
for _, p in ipairs(Ai) do mark(p, "dot", 5, 15) end
mark(M, "dot", 5, 6) mark(K, "dot", 6, 14)
label("$C$", C, nil, 9) label("$A$", A, nil, 9) label("$B$", B, nil, 9)
for i = 1, 4 do label("$A_" .. i .. "$", Ai[i]) end
label("$M$", M, nil, 6) label("$K$", K, nil, 14)
caption(string.format("lambda (1.5) = %.6f = A1K/A1A2 = %.6f", lam, dist(Ai[1], K) / dist(Ai[1], Ai[2])), "bottom", 7)
