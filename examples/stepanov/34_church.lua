-- Example 34 — Schematic 3-D church (Vladimir–Suzdal architecture)
-- A surface net: the 7 nodes of a spline "meridian" slide along guide curves - five circles of
-- the onion dome and the drum, and on each of two walls the wall top with three zakomary arches,
-- z = |cos b|/(4 + b^2) + 2, and the ground line with pilaster spikes, z = (1 - |cos b|)^10,
-- b = 3 pi t1/2 (§H row 27).  Every node tangent points straight down, given as the vector
-- (0, 0, -1) (§H row 8, explicit vectors), sides .5, n = m = 2, t0 = .5; the meridians for
-- t1 = -1, -8/9, ..., 1 on each wall make the net.  Oblique projection (§H row 23):
-- C0 = (320, 400), unit 60, ellipse ratio .3, turned by pi/5.
-- What shows: the white guide curves traced by the nodes (2001 positions per wall: the front
-- half-arcs of the dome and drum, the arched wall tops, the ground lines with their spikes),
-- a small painted knob (CIRCLE with aspect 5) and the cross on top.
-- Colour 0: the listing draws the net itself with `pset (x, y), 0`, the background colour, so
-- the church's meridians are invisible; they only erase a few guide pixels.  This script keeps
-- that faithfully; 34v_colour8_church.lua draws the net in colour 8.
-- Loops as QBasic runs them (qb.range: 2001 positions, 19 meridians of 101 points per piece,
-- the cross's 7 x 110 and 81 x 11 pixels).

local pi, cos, sin, abs = math.pi, math.cos, math.sin, math.abs
local NET_COLOUR = tonumber((...)) or 0             -- as printed: the background (34v passes 8)

local pr = oblique(P(320, 400), 60, .3, pi/5)
local r = {.05, .05, .6, .3, .3}                    -- the circles of the dome and the drum:
local h = {3.9, 3.8, 3.1, 2.8, 2.5}                 -- radius and height

-- the 7 nodes of the meridian at t1 in [-1, 1] on wall j
local function nodes(j, t1)
  local a = j == 1 and pi*t1/4 - pi/2 or -pi*t1/4 - pi   -- angle on the circles
  local N = {}
  for i = 1, 5 do N[i] = P(r[i]*cos(a), r[i]*sin(a), h[i]) end
  local x, y = t1, -1                               -- wall 1: the face y = -1
  if j == 2 then x, y = -1, t1 end                  -- wall 2: the face x = -1
  local b = 3*pi*t1/2
  N[6] = P(x, y, abs(cos(b))/(4 + b^2) + 2)         -- the top with three zakomary
  N[7] = P(x, y, (1 - abs(cos(b)))^10)              -- the ground line and the pilasters
  return N
end

local knob = pr(P(0, 0, h[1]))
circle(knob, 4, nil, nil, nil, 5); paint(knob)

local down = V(0, 0, -1)
for j = 1, 2 do
  for t1 in qb.range(-1, 1, .001) do                -- the guide curves
    for _, X in ipairs(nodes(j, t1)) do pset(pr(X)) end
  end
  for t1 in qb.range(-1, 1.01, 1/9) do              -- the net of meridians
    local meridian = stroke{nodes = nodes(j, t1), ein = {down, down, down, down, down, down, down},
                            rin = .5, rout = .5}
    meridian:draw{t = {0, 1, .01}, qb = true, map = pr, color = NET_COLOUR}
  end
end

for x in qb.range(-r[1], r[1] + .01, r[1]/3) do     -- the cross, in the plane y = 0
  for z in qb.range(h[1] - .1, h[1] + 1, .01) do pset(pr(P(x, 0, z))) end
end
for x in qb.range(-.4, .4, .01) do
  for z in qb.range(h[1] + .5, h[1] + .61, .01) do pset(pr(P(x, 0, z))) end
end
