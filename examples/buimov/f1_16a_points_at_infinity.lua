-- Points at infinity: [4 3 h] runs out along y = 3x/4 as h goes to 0
-- Buimov §1.7.7 (the table of points at infinity): [4 3 1], [4 3 1/2], [4 3 1/4], [4 3 1/8] are the
-- points (4, 3), (8, 6), (16, 12), (32, 24); [4 3 0] is the point at infinity of the line
-- y = (3/4) x (the book's prose says "[3 4 h]", a misprint; its table has [4 3 h]).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
fit{around = {P(-2, -2), P(36, 27)}, pad = 2.6, band = 20}
axes{x = {-2, 36}, y = {-2, 27}, ticks = 0, labels = false, color = 8}
label("$x$", P(36, 0), "s", 8); label("$y$", P(0, 27), "w", 8)
pen{dash = {4, 3}}; line(P(0, 0), P(34, 25.5), 8); pen()
for _, h in ipairs{1, 1 / 2, 1 / 4, 1 / 8} do
  local p = P(4 / h, 3 / h)
  dot(p, string.format("[4 3 %s]", h == 1 and "1" or "1/" .. math.floor(1 / h + 0.5)), 14)
end
arrow(P(32, 24), P(35.5, 26.625), "end", 12); label("[4 3 0]", P(35.5, 26.625), nil, 12)
caption("x* = 4/h, y* = 3/h:  h = 1/100 gives (400, 300), h = 10^-6 (4e6, 3e6)", "bottom", 7)
