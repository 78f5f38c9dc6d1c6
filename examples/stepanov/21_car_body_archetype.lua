-- Example 21 — Archetype of a passenger-car body
-- Example 20's strip system, y = f(x) + s(t) (g(x) - f(x)) with the clamped smoothstep s, between
-- a floor f(x) = -1 - x^2/180 and a roof g(x) = 1 - x^6/(1 + x^6) - x^2/20 (the cabin bump, then
-- hood and trunk).  White: the two boundary graphs across the screen.  White, thick: concentric
-- ellipses x = 1.5 r cos u + 1/3, t = r sin(u)/2 + 1/2 drawn in the system; the outer ones are
-- pressed into the strip and one of them is the car body: cabin on top, hood and trunk lower.
-- Scale 100, origin (320, 240), y up.
-- QBasic's loop counts matter: `for r = .2 to 1.8 step .2` accumulates in single precision and
-- stops at r = 1.6, so there are 8 curves, not 9 (qb.range).  The listing's strict IF chain
-- keeps s at t exactly .5 (every curve's first point), so the very first point takes QBasic's
-- initial s = 0: a stray dot on the floor (C:clamp{qb = true}), hidden under the outer curves
-- pressed against it.

screen(12)
local pi, cos, sin = math.pi, math.cos, math.sin
local floor = function(x) return -1 - x^2/180 end
local roof = function(x) return 1 - x^6/(x^6 + 1) - x^2/20 end
local strip = graphs(floor, roof):post(screenmap(320, 240, 100))
local C = strip:clamp{t2 = true, qb = true}

for _, t in ipairs{0, 1} do                          -- floor and roof
  strip:draw(function(x) return x, t end, {t = {-3.2, 3.2, .01}, qb = true})
end

for r in qb.range(.2, 1.8, .2) do                    -- 8 curves, as in QBasic
  C:draw(function(u) return 1.5*r*cos(u) + 1/3, r*sin(u)/2 + 1/2 end,
         {t = {0, 2*pi, pi/500}, qb = true, brush = "dot"})
end
