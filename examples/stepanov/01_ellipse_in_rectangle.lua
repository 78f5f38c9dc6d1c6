-- Example 1 — Ellipse inscribed in a rectangle
-- The rectangle a <= y <= b, c <= x <= d (white box) and the ellipse touching its four sides
-- (white, one pixel per sample). Kinematic construction: a vertical segment of the rectangle's
-- height oscillates horizontally, x = x0 + r cos u, and a point oscillates along it a quarter
-- period later, at (1 + sin u)/2 of its length (§H building block 2, the harmonic oscillation
-- on a segment), u = 2 pi t.
-- The construction is written once as a point equation in t (docs/equations.md) and compiled.
-- QBasic runs `for t = 0 to 1 step .001` 1001 times: qb = true keeps that count.

screen(12)
local a, b, c, d = 100, 400, 200, 300
line(c, a, d, b, nil, "b")                   -- the rectangle, in the default colour

local x0, r = (c + d)/2, (d - c)/2           -- centre abscissa and horizontal amplitude
local t = param "t"
local u = 2*math.pi*t
local x = x0 + r*math.cos(u)                 -- the moving vertical segment from (x, a) to (x, b)
local M = lerp(P(x, a), P(x, b), (1 + math.sin(u))/2)
plot(curve(M, 0, 1), {t = {0, 1, .001}, qb = true})
