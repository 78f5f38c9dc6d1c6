-- Example 19 — Curvilinear system spanned by two function graphs; concentric ellipses in it
-- The graphs of f(x) = (x - e^(x - 1))/3 and g(x) = sin(5x)/2 + 2 span the system whose
-- coordinate lines are the curves y = f(x) + t (g(x) - f(x)) (a barycentric combination of the
-- two graphs; t = 0 and t = 1 are the graphs themselves) and the verticals x = const.
-- White, thick: the two graphs.  White: the lines t = -1.5, -1.3, ..., 2.9, fanning out and
-- leaving the screen, and the dotted verticals x = -3.2, -3.0, ..., 3.0.  Blue, thick: the
-- concentric ellipses x = 2r cos u, t = r sin u + 1/2 drawn in the system: they carry the ripple
-- of the sine.  Scale 50, origin (320, 300), y up.
-- QBasic's loop counts matter here: `for r = .2 to 1.6 step .2` accumulates in single precision
-- and stops at r = 1.4, so there are 7 ellipses, not the 8 of a double-precision loop; the
-- verticals likewise stop before x = 3.2.  Hence qb = true and qb.range.
-- (The article's prose garbles f into "-e^(x-1) + sin 5x/2 + 2"; the listing is intact.)

screen(12)
local pi, cos, sin, exp = math.pi, math.cos, math.sin, math.exp
local f = function(x) return (x - exp(x - 1))/3 end
local g = function(x) return sin(5*x)/2 + 2 end
local C = graphs(f, g):post(screenmap(320, 300, 50))

for _, t in ipairs{0, 1} do                          -- the graphs of f and g
  C:draw(function(x) return x, t end, {t = {-3.2, 3.2, .01}, qb = true, brush = "dot"})
end

C:grid{t1 = {-3.2, 3.2, .2, .01},                    -- verticals x = const
       t2 = {-1.5, 3.001, .2, fine = {-1.5, 3, .01}}, -- lines t = const
       qb = true}

for r in qb.range(.2, 1.6, .2) do                    -- 7 ellipses, as in QBasic
  C:draw(function(u) return 2*r*cos(u), r*sin(u) + 1/2 end,
         {t = {0, 2*pi, pi/1000}, qb = true, brush = "dot", color = 1})
end
