-- Example 13 — Profile of a human face
-- A head looking left, drawn from 2n = 16 archetype points taken from a drawing: the points
-- themselves (small circles), the Fourier archetype through them (example 12's closed
-- trigonometric curve, dark grey), and the profile, a closed one-stroke spline through the
-- points (example 10's quadrilateral splines with the n = 2 half-spline g = 2t^2 / 1 - 2(1 - t)^2).
-- The article prints only the points; the rest is reconstructed from its text, as in the cleaned
-- listing: the tangent at each node is parallel to the chord of its two neighbours, both sides of
-- each quadrilateral are a third of the chord, and the archetype colour 8 is assumed.
-- The points are screen pixels (y down); the last one repeats the first, closing the outline,
-- whose neck runs off the bottom of the screen.

screen(12)
local archetype = {
  P(400, 180), P(295, 50), P(110, 95), P(80, 215), P(37, 285), P(75, 300), P(65, 320), P(75, 335),
  P(80, 350), P(100, 400), P(175, 365), P(180, 505), P(270, 470), P(340, 450), P(330, 320), P(400, 180),
}
for _, A in ipairs(archetype) do circle(A, 3) end

-- the Fourier archetype "conveys the drawing poorly": u over 0..2 pi in steps of pi/(64 n)
fourier(archetype):draw{t = {0, 2*math.pi, math.pi/512}, qb = true, color = 8}

-- so splines are needed: one stroke through the 15 distinct points, closed
local nodes = {table.unpack(archetype, 1, 15)}
local profile = stroke{nodes = nodes, closed = true}    -- chord tangents, sides chord/3, n = m = 2
profile:draw{t = {0, 1, .001}, qb = true}
