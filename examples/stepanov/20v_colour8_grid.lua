-- Example 20 (variant) — The strip system with its boundaries and grid in colour 8
-- A labelled variant, not in the article: example 20 draws the boundary graphs and the grid of
-- its system in colour 0, the background, so they are invisible and only the circles show.
-- Here the same drawing is made in dark grey (8), to show what the system looks like: the
-- strip between f(x) = (x - e^(x - 1))/3 - 1 and g(x) = sin(5x)/2 + 3, its 41 lines
-- y = f + s(t)(g - f), t = -.5, -.45, ..., 1.5, crowding onto the two boundaries where the
-- clamped smoothstep s(t) stops at 0 and 1, and the 32 verticals; over them the five blue
-- circles x = r cos u, t = r sin u + .5 pressed into the strip.
-- Everything else is example 20 as printed (20_system_in_a_strip.lua).

screen(12)
local pi, cos, sin, exp = math.pi, math.cos, math.sin, math.exp
local f = function(x) return (x - exp(x - 1))/3 - 1 end
local g = function(x) return sin(5*x)/2 + 3 end
local strip = graphs(f, g):post(screenmap(320, 300, 50))
local C = strip:clamp{t2 = true, qb = true}          -- t -> s(t), the listing's IF chain
local shown = 8                                      -- instead of the listing's 0

for _, t in ipairs{0, 1} do                          -- the boundary graphs f and g
  strip:draw(function(x) return x, t end, {t = {-3.2, 3.2, .01}, qb = true, brush = "dot", color = shown})
end
C:grid{t1 = {-3.2, 3.2, .2, .01},                    -- verticals x = const
       t2 = {-.5, 1.501, .05, fine = {-.5, 1.5, .01}}, -- lines t = const
       qb = true, color = shown}

for r in qb.range(.1, 1.301, .3) do
  C:draw(function(u) return r*cos(u), r*sin(u) + .5 end,
         {t = {0, 2*pi, pi/1000}, qb = true, brush = "dot", color = 1})
end
