-- Konopatsky §4.11 (Fig. 4.10): exponential interpolation against the parabola
-- Three chosen nodes at t = 0, 1/2, 1 (the book gives neither its nodes nor its k): the
-- exponential prototype (4.39) with k = (0.5, -1, 2) (brown) against the parabola (4.10)
-- (blue); its weights do not sum to 1 (interp.basis reports it), so the curve moves when the
-- origin does: the same nodes shifted by (40, 0) give the dashed curve, shifted back.
local function mark(p, name, _) circle(p, 0.06, 15) label(name, p, nil, 15) end
local M = {P(0, 0), P(2, 3), P(5, 1)}
local shift = V(40, 0)
local Ms = {M[1] + shift, M[2] + shift, M[3] + shift}
for i, kind in pairs{[1] = "exp"} do
  fit{around = {P(-1, -2), P(6, 5)}}
  local k = kind == "exp" and {0.5, -1, 2} or {0.5, -1}
  interp.lagrange(M):draw{color = 9}
  local c = interp.prototype(kind, M, k)
  c:draw{color = 6}
  local cs = interp.prototype(kind, Ms, k)
  pen{dash = {4, 3}}
  curve(function(t) return cs(t) - shift end, 0, 1):draw{color = 6}
  pen()
  for j, p in ipairs(M) do mark(p, "$M_" .. j .. "$", "n") end
  local _, affine = interp.basis(kind == "exp"
    and {function(t) return math.exp(0.5 * t) end, function(t) return math.exp(-t) end, function(t) return math.exp(2 * t) end}
    or {function(t) return math.exp(0.5 * t) end, function(t) return math.exp(-t) end,
        function(t) return 1 - math.exp(0.5 * t) - math.exp(-t) end}, M, {0, 0.5, 1})
  label(string.format("%s  weights sum to 1: %s", kind == "exp" and "(4.39)" or "constrained", tostring(affine)),
        P(-0.8, -1.6), "e", 7)
end
