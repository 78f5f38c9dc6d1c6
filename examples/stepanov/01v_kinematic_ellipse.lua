-- Example 1 (animated) — The ellipse drawn by a point running along a moving segment
-- Stepanov's kinematic method (§3 of the article, example 1): the vertical segment of the
-- rectangle's height slides across it, x = x0 + r cos u, while a point runs along it a quarter
-- period later, at (1 + sin u)/2 of its length, u = 2 pi t.  The time t is a slider with
-- {animate = true}: `pointcalc 01v_kinematic_ellipse.lua --frames 48 -o ellipse.svg` writes the
-- construction moving, `pointcalc serve 01v_kinematic_ellipse.lua` shows it with a slider, and
-- a plain run draws the moment t = 0.3 with the trace so far.

local t = slider("t", 0, 1, .3, {animate = true})
local a, b, c, d = 100, 400, 200, 300
line(c, a, d, b, 7, "b")                                   -- the rectangle
local x0, r = (c + d) / 2, (d - c) / 2
local function M(s)                                        -- the running point at time s
  local u = 2 * math.pi * s
  local x = x0 + r * math.cos(u)
  return lerp(P(x, a), P(x, b), (1 + math.sin(u)) / 2)
end
if t > 0 then plot(M, {t = {0, t, .001}, color = 14}) end  -- the trace so far, one path
local u = 2 * math.pi * t
local x = x0 + r * math.cos(u)
line(x, a, x, b, 10)                                       -- the moving segment
circle(M(t), 4, 12)
label("M", M(t), "ne", 12)
label(string.format("t = %.3f", t), P(250, 440), "c", 15)
