-- Korotky (2015) Fig. 4a, 4b: the elliptic domes, in perspective, hidden lines left out
-- Left (4a): the dome over the rectangle ABCD, 2a0 x 2b0 = 4 x 2, height c0 = 1.5: the
-- semi-ellipse e (planes x = const, resting on AB and CD) moves along the guide g, the
-- semi-ellipse in the mid-plane y = b0; the sections y = const are semi-ellipses too, with
-- variable eccentricity; the tangent planes along the sides are vertical.  Inset: near the
-- corner A the dome is the elliptic cone z^2/c0^2 = 4xy/(a0 b0) (the paper's one surviving
-- formula): the dome's sections (cyan) and the cone's rulings from A (magenta) near the corner.  Right (4b): the dome over the right triangle ABC (legs 1.6, AC on y = 0, AB
-- on x = 0), apex D of height 1 over the centroid, z^2 = 27 h^2 l1 l2 l3: the sections x + y =
-- const (family a, parallel to BC), x = const (family b, parallel to AB), and y = const with the
-- guide n through D, which rests on AB and BC.  Inset: the neighbourhood of A, where the dome
-- is the cone z^2 = 27 h^2 xy / 1.6^2 (the same comparison).
-- an inset: the dome's sections x = const and y = const near the corner A (cyan) and the
-- rulings of the cone there (magenta, straight lines from A), over the square 0.3 x 0.3
local function inset(x0, y0, z, zc)
  camera(map.translate(V(x0, y0)) * map.scale({190, -190}) *
         map.perspective(P(-1.2, -1.6, 1.4), P(.15, .15, .25)), {hidden = "show"})
  local r = .3
  for k = 1, 4 do
    local c = r * k / 4
    curve(function(t) return P(c, t, z(c, t)) end, 0, r):draw{color = 11}
    curve(function(t) return P(t, c, z(t, c)) end, 0, r):draw{color = 11}
  end
  for k = 1, 5 do
    local th = math.pi / 2 * k / 6
    local x, y = r * math.cos(th), r * math.sin(th)
    line(P(0, 0, 0), P(x, y, zc(x, y)), 13)
  end
  line(P(0, 0, 0), P(r, 0, 0), 7); line(P(0, 0, 0), P(0, r, 0), 7)
  label("A", P(0, 0, 0))
  camera(nil)
end

-- 4a -----------------------------------------------------------------------------------------
local a0, b0, c0 = 2, 1, 1.5
camera(map.translate(V(170, 300)) * map.scale({58, -58}) * map.perspective(P(-5, -9, 7), P(2, 1, .4)),
       {hidden = "hide"})
local rect = korotky.dome_rect(a0, b0, c0)
rect:wireframe{nu = 10, nv = 8, color = 11}
local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(4, 2, 0), P(0, 2, 0)
line(A, B, 7); line(B, C, 7); line(C, D, 7); line(D, A, 7)
local g = rect:iso("v", .5)                   -- the guide g: the section y = b0
g:draw{color = 14}
rect:iso("u", .3):draw{color = 12}            -- one position of the moving semi-ellipse e
label("A", A); label("B", B); label("C", C); label("D", D)
label("g", g(.7)); label("e", rect:iso("u", .3)(.25))
camera(nil)
local function zr(x, y) return c0 * math.sqrt(math.max(0, x * (2 * a0 - x) * y * (2 * b0 - y))) / (a0 * b0) end
inset(90, 150, zr, function(x, y) return c0 * math.sqrt(4 * x * y / (a0 * b0)) end)

-- 4b -----------------------------------------------------------------------------------------
local h, s = 1, 1.6
local TA, TC, TB = P(0, 0, 0), P(s, 0, 0), P(0, s, 0)
camera(map.translate(V(480, 300)) * map.scale({118, -118}) * map.perspective(P(-2.5, -4.5, 3.5), P(.55, .55, .3)),
       {hidden = "hide"})
-- dome_tri(X, Y, Z): its u-isolines are the ellipses parallel to the side YZ opposite X
korotky.dome_tri(TA, TC, TB, h):wireframe{nu = 7, nv = 0, color = 10}   -- family a (parallel to BC)
korotky.dome_tri(TC, TA, TB, h):wireframe{nu = 7, nv = 0, color = 13}   -- family b (parallel to AB)
local byAC = korotky.dome_tri(TB, TA, TC, h)                           -- parallel to AC (y = const)
byAC:wireframe{nu = 6, nv = 0, color = 11}
local n = byAC:iso("u", 2 / 3)                -- y = s/3: the guide n through the apex D
n:draw{color = 14}
line(TA, TC, 7); line(TC, TB, 7); line(TB, TA, 7)
local top = P(s / 3, s / 3, h)
mark(top, "dot", 4, 15)
label("D", top); label("n", n(.2))
label("A", TA); label("B", TB); label("C", TC)
camera(nil)
local K = 27 * h * h / (s * s)
inset(400, 150, function(x, y) return math.sqrt(math.max(0, 27 * h * h * (x / s) * (y / s) * (1 - (x + y) / s))) end,
      function(x, y) return math.sqrt(K * x * y) end)
label("4a  dome on a rectangle", P(40, 460), "e", 11)
label("4b  dome on a triangle", P(380, 460), "e", 10)
