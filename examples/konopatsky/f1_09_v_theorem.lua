-- Konopatsky §1.3.4 (Fig. 1.9): the V-theorem, the volume ratio is the determinant of the parameters
-- Chosen tetrahedron A(5,0,0), B(0,5,0), C(0,0,0), D(1.5,1.5,4.5) and the inner tetrahedron
-- A_i = Ap_i + Bq_i + Cr_i + Ds_i with the rows (0.55, 0.15, 0.15, 0.15), (0.15, 0.55, 0.15,
-- 0.15), (0.15, 0.15, 0.55, 0.15), (0.15, 0.15, 0.15, 0.55): V_A1A2A3A4/V_ABCD is their
-- determinant (konopatsky.simplex_ratio; the print's det/det is 1), against the volumes from
-- the coordinates.  Axonometric view with z up.
local A, B, C, D = P(5, 0, 0), P(0, 5, 0), P(0, 0, 0), P(1.5, 1.5, 4.5)
local rows = {{0.55, 0.15, 0.15, 0.15}, {0.15, 0.55, 0.15, 0.15}, {0.15, 0.15, 0.55, 0.15},
              {0.15, 0.15, 0.15, 0.55}}
local T = {}
for i, r in ipairs(rows) do T[i] = A * r[1] + B * r[2] + C * r[3] + D * r[4] end
local function vol(p, q, r, s) return dot(q - p, cross(r - p, s - p)) / 6 end
local view = map.view{azimuth = -35, elevation = 20}
camera(view)
fit{around = {A, B, C, D}, pad = 0.6}
local function edges(v, c)
  for i = 1, 4 do for j = i + 1, 4 do line(v[i], v[j], c) end end
end
edges({A, B, C, D}, 9)
edges(T, 14)
for _, p in ipairs{A, B, C, D} do mark(p, "dot", 5, 15) end
for _, p in ipairs(T) do mark(p, "dot", 5, 14) end
label("$A$", A) label("$B$", B) label("$C$", C) label("$D$", D)
for i = 1, 4 do label("$A_" .. i .. "$", T[i], nil, 14) end
camera()
caption(string.format("det = %.6f,  V(A1A2A3A4)/V(ABCD) = %.6f", konopatsky.simplex_ratio(rows),
  vol(T[1], T[2], T[3], T[4]) / vol(A, B, C, D)), "bottom", 7)
