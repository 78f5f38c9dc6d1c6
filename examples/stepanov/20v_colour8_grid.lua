-- Example 20 (variant) — The strip system with its boundaries and grid in colour 8
-- A labelled variant, not in the article: example 20 draws the boundary graphs and the grid of
-- its system in colour 0, the background, so they are invisible and only the circles show.
-- Here the same drawing is made in dark grey (8), to show what the system looks like: the
-- strip between f(x) = (x - e^(x - 1))/3 - 1 and g(x) = sin(5x)/2 + 3, its 41 lines
-- y = f + s(t)(g - f), t = -.5, -.45, ..., 1.5, crowding onto the two boundaries where the
-- clamped smoothstep s(t) stops at 0 and 1, and the 32 verticals; over them the five blue
-- circles x = r cos u, t = r sin u + .5 pressed into the strip.
-- Everything else is example 20 as printed (20_system_in_a_strip.lua).

-- the same script as the faithful figure, with the colour as its argument
local here = arg[0]:match("^(.-)[^/]*$")
assert(loadfile(here .. "20_system_in_a_strip.lua"))(8)
