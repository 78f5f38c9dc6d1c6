-- Konopatsky §2.4 (Fig. 2.30): the parabola of one ratio by an angle, and the parallelogram CKML
-- The digest's C(0,0), A(4,0), B(1,3): the curve M = (A - C)t'^2 + (B - C)t^2 + C (green), its
-- parallelogram CKML with K = (A - C)t'^2 + C on CA and L = (B - C)t^2 + C on CB at t = 0.55,
-- and the angle phi = MCA of the angular parametrisation (2.128).  The same curve by sigma =
-- CK + KM (§2.4.2: the print calls it |CM|, which it is not) in two branches, dotted.
local function mark(p, name, _, c) circle(p, 0.04, c or 15) label(name, p, nil, c or 15) end
local C, A, B = P(0, 0), P(4, 0), P(1, 3)
window(-0.8, -0.7, 4.8, 3.5)
path({A, C, B}, {color = 8})
local arc = conic.reparam{C = C, A = A, B = B}            -- by the angle phi in [0, gamma]
arc:draw{color = 10}
for _, br in ipairs{1, 2} do
  local s = conic.reparam{C = C, A = A, B = B, by = "sigma", branch = br}
  for i = 0, 12 do circle(s(s.t0 + (s.t1 - s.t0) * i / 12), 0.03, br == 1 and 14 or 11) end
end
local t = 0.55
local K, L = (A - C) * (1 - t) ^ 2 + C, (B - C) * t * t + C
local M = K + L - C
path({C, K, M, L, C}, {color = 7})
line(C, M, 12)
local phi = angle(C, A, M)
local pts = {}
for i = 0, 12 do local a = phi * i / 12 pts[#pts + 1] = C + V(math.cos(a), math.sin(a)) * 0.6 end
path(pts, {color = 12})
label("$\\varphi$", C + V(math.cos(phi / 2), math.sin(phi / 2)) * 0.75, "c", 12)
mark(C, "$C$", "sw") mark(A, "$A$", "se") mark(B, "$B$", "n") mark(K, "$K$", "s", 11) mark(L, "$L$", "nw", 11)
mark(M, "$M$", "ne", 14)
label(string.format("t = %.2f: phi = %.4f, CK + KM = %.4f, |CM| = %.4f", t, phi,
      dist(C, K) + dist(K, M), dist(C, M)), P(-0.7, -0.5), "e", 7)
