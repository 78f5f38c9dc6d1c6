-- Example 10 (animated) — The one-stroke curve drawn piece by piece
-- The stroke of example 10 through four nodes, traced as its parameter s runs over 0..3: on
-- the piece under way, the quadrilateral N_i P Q N_(i+1), the points M on N_i P and N on Q N_(i+1)
-- moving with t, and X = M + g(t)(N - M) (§H blocks 7 and 8).  s is a slider {animate = true}.

local s = slider("s", 0, 3, 1.6, {animate = true})
local nodes = {P(100, 300), P(200, 150), P(300, 50), P(400, 100)}
local S = stroke{nodes = nodes, uin = {0, .3, .85, 0}, kink = 0, rin = {50, 60, 40, 50},
  rout = {70, 30, 80, 40}, n = {2, 4, 6, 2}, m = {7, 5, 3, 2}, t0 = {.3, .5, .7, .2}}
for i, N in ipairs(nodes) do circle(N, 5, 15); label("N" .. i, N, "se", 15) end
if s > 0 then S:sub(0, s):draw{color = 14} end            -- the curve so far, one path
local i = math.min(math.floor(s), 2)                        -- the piece under way (0-based)
local t = s - i
local A, Pp, Q, B = S:controls(i + 1)
pen{dash = {3, 3}}
path({A, Pp, Q, B}, {color = 8})
pen()
local M, N = lerp(A, Pp, t), lerp(Q, B, t)
line(M, N, 10)
circle(M, 3, 10); label("M", M, "nw", 10)
circle(N, 3, 10); label("N", N, "ne", 10)
circle(S(s), 4, 12); label("X", S(s), "s", 12)
label(string.format("piece %d, t = %.3f", i + 1, t), P(250, 440), "c", 15)
