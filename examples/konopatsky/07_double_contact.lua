-- Konopatsky §3.4 (Fig. 3.6 a, b): curves of double contact, f = v^2 and f = sqrt(v)
-- Simplex A(0,0), B(10,0), C(4,6) (the digest's defaults); the first-generation arcs P
-- (k_p = 0.3) and Q (k_q = 0.7) in red, the second-generation curve M = P(1 - f) + Q f in
-- green, with the segment PQ at v = 0.4.  Left f = v^2, right f = sqrt(v).  P, Q (the
-- engineering-discriminant conics (2.97)) and M are point equations in v, compiled.
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
local fs = {{"f = v^2", function(v) return v * v end}, {"f = sqrt(v)", math.sqrt}}
for i, f in ipairs(fs) do
  view(10 + (i - 1) * 315, 60, 310 + (i - 1) * 315, 285)
  window(-0.8, -1.2, 10.8, 7.5)
  path({A, C, B}, {color = 8})
  local v = param "v"
  local function ed(k)                                  -- (2.97), the ED conic of k
    local den = k*(1 - 2*v)^2 + 2*v*bar(v)
    return (A - C)*(k*bar(v)^2/den) + (B - C)*(k*v^2/den) + C
  end
  local Pv, Qv = ed(0.3), ed(0.7)
  local Pc, Qc = curve(Pv, 0, 1), curve(Qv, 0, 1)
  Pc:draw{color = 12} Qc:draw{color = 12}
  local M = curve(Pv*(1 - f[2](v)) + Qv*f[2](v), 0, 1)  -- M = P(1 - f(v)) + Q f(v)
  M:draw{color = 10}
  v = 0.4
  line(Pc(v), Qc(v), 7)
  circle(M(v), 0.1, 15)
  label("$P$", Pc(v), nil, 12) label("$Q$", Qc(v), nil, 12) label("$M$", M(v), nil, 10)
  label("$A$", A, nil, 15) label("$B$", B, nil, 15) label("$C$", C, nil, 15)
  label(f[1], P(0, -0.9), "e", 7)
end
