-- Konopatsky §2.3 (Fig. 2.29): the redundant parametrisation of the plane and its curves
-- The digest's simplex C(0,0), A(1,0), B(0,1): P = (A - C)u' + C on CA, Q = (B - C)v + C on CB
-- and K = AQ x BP (2.120, with the corrected u'v').  Consistent motions of P and Q give contour
-- arcs AB: u = v = t (2.121, green: the engineering-discriminant arc with k = 2/3), u = t,
-- v = t^2 (yellow) and u = t^2, v = t (cyan, chosen); the scheme at u = v = 0.4.
local function mark(p, name, _, c) circle(p, 0.012, c or 15) label(name, p, nil, c or 15) end
local C, A, B = P(0, 0), P(1, 0), P(0, 1)
window(-0.3, -0.2, 1.4, 1.1)
path({A, C, B}, {color = 8}) line(A, B, 8)
conic.redundant(C, A, B):draw{color = 10}
local function family(fu, fv, color)
  curve(function(t) return conic.redundant(C, A, B, fu(t), fv(t)) end, 0, 1):draw{color = color}
end
family(function(t) return t end, function(t) return t * t end, 14)
family(function(t) return t * t end, function(t) return t end, 11)
local u = 0.4
local Pp, Q = (A - C) * (1 - u) + C, (B - C) * u + C
local K = conic.redundant(C, A, B, u, u)
pen{dash = {4, 3}} line(A, Q, 7) line(B, Pp, 7) pen()
mark(C, "$C$", "sw") mark(A, "$A$", "se") mark(B, "$B$", "nw") mark(Pp, "$P$", "s", 12) mark(Q, "$Q$", "w", 12)
mark(K, "$K$", "ne", 14)
label("u = v = t (2.121)", P(0.75, 0.95), "e", 10)
label("u = t, v = t^2", P(0.75, 0.88), "e", 14)
label("u = t^2, v = t", P(0.75, 0.81), "e", 11)
