-- Example 34 (variant) — Schematic 3-D church with its spline net drawn in colour 8
-- NOT THE LISTING AS PRINTED: example 34 draws the net of meridians with `pset (x, y), 0`, the
-- background colour, so the faithful figure (34_church.lua) shows only the guide curves, the
-- knob and the cross.  This variant draws the same net in colour 8 (dark grey), as the digest
-- recommends: the church appears - a bulbous onion dome on a drum, and two walls with three
-- zakomary arches each, all as dense vertical meridians.  ("0" may be an OCR misreading of
-- "8"; that is unverified.)  Everything else is example 34 unchanged:
-- the 7 nodes of each meridian slide along five circles of the dome and the drum, the wall top
-- z = |cos b|/(4 + b^2) + 2 (zakomary) and the ground line z = (1 - |cos b|)^10 (pilasters),
-- b = 3 pi t1/2 (§H row 27); every node tangent is (0, 0, -1) (§H row 8, explicit vectors),
-- sides .5, n = m = 2, t0 = .5; 19 meridians t1 = -1, -8/9, ..., 1 per wall; oblique projection
-- C0 = (320, 400), unit 60, ellipse ratio .3, turned by pi/5 (§H row 23).  The guide curves
-- (white) are drawn before each wall's net, which paints over some of their pixels.

-- the same script as the faithful figure, with the colour as its argument
local here = arg[0]:match("^(.-)[^/]*$")
assert(loadfile(here .. "34_church.lua"))(8)
