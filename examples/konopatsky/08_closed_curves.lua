-- Konopatsky §3.5 (Table 3.2): closed curves of two arcs run in opposite directions
-- Simplex A(0,0), B(10,0), C(4,6).  Rows: k_P = 0.8, k_Q = 0.5 (ellipse + parabola) and
-- k_P = 0.9, k_Q = 0.6 (two ellipses); columns: scheme 1 and scheme 2 (with the corrected Q).
-- Every curve starts and ends at B, where it has a corner: a wing or blade profile.
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
local rows = {{0.8, 0.5}, {0.9, 0.6}}
for r, k in ipairs(rows) do
  for s = 1, 2 do
    view(10 + (s - 1) * 315, 10 + (r - 1) * 235, 310 + (s - 1) * 315, 230 + (r - 1) * 235)
    window(-1, -1.2, 11, 7.6)
    path({A, C, B, A}, {color = 8})
    oneratio.closed(A, B, C, k[1], k[2], s):draw{color = 10}
    label("$A$", A, nil, 15) label("$B$", B, nil, 15) label("$C$", C, nil, 15)
    label(string.format("scheme %d  kP = %.1f  kQ = %.1f", s, k[1], k[2]), P(-0.8, -0.9), "e", 7)
  end
end
