-- The QBasic drawing layer: every statement once
-- SCREEN 12 is the default canvas: 640x480, 16 colours, y axis down.
screen(12)
-- a box outline, a filled box and a segment
line(40, 40, 240, 180, 9, "b")
line(60, 60, 120, 120, 1, "bf")
line(40, 200, 240, 200, 15)
-- circles: full, arc, arc with radii (negative angles), and the aspect rule
circle(400, 110, 70, 14)
circle(400, 110, 50, 12, 0, math.pi)
circle(400, 110, 30, 10, -math.pi / 4, -7 * math.pi / 4)
circle(560, 110, 60, 11, nil, nil, 0.5)   -- aspect below 1: flatter
circle(560, 110, 60, 13, nil, nil, 2)     -- above 1: narrower
-- PAINT fills up to a border colour
circle(140, 330, 80, 15)
line(60, 330, 220, 330, 15)
paint(140, 300, 4, 15)
paint(140, 360, 2, 15)
-- a dotted curve with PSET, and WINDOW for world coordinates with y up
window(-1, -1.2, 1, 1.2)
for i = 0, 2000 do
  local t = 2 * math.pi * i / 2000
  pset(0.45 + 0.4 * math.sin(3 * t), -0.55 + 0.4 * math.sin(2 * t), 10)
end
