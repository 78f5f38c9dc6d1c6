-- Fig. 3.1 (animated) — The curve of one ratio by a moving simplex
-- Konopatsky §3.1, eq. (3.1) with its misprint corrected: N runs along AC and M along the moving
-- segment NB with one ratio, AN/AC = NM/NB = t, so N = A(1 - t) + C t, M = N(1 - t) + B t and
-- M = (A - C) t̄² + (B - C) t + C (the printed "C t̄" term breaks the membership condition).
-- BC is tangent at B; at A the curve leaves along the median, not along AC.  The ratio t is a
-- slider {animate = true}: docs/live.md shows the page and the frames.

local t = slider("t", 0, 1, .55, {animate = true})
local A, B, C = P(100, 400), P(540, 380), P(260, 80)
path({A, C, B}, {color = 7})
for name, q in pairs{A = A, B = B, C = C} do
  circle(q, 3, 15)
  label(name, q, nil, 15)
end
local function M(s) return lerp(lerp(A, C, s), B, s) end    -- N = lerp(A, C, s), then toward B
if t > 0 then plot(M, {t = {0, t}, color = 14}) end            -- the curve so far
pen{dash = {4, 3}}
plot(M, {t = {t, 1}, color = 8})                              -- and still to come
pen()
local N = lerp(A, C, t)
line(N, B, 10)                                                -- the moving 1-simplex NB
circle(N, 3, 10); label("$N$", N, nil, 10)
circle(M(t), 4, 12); label("$M$", M(t), nil, 12)
label(string.format("AN/AC = NM/NB = t = %.2f", t), P(320, 450), "c", 15)
