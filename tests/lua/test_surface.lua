-- The one surface type through Lua: every constructor of surface.*, the methods (points,
-- partial derivatives, normals, iso-curves, maps), wireframes through the camera with hidden
-- lines left out or dashed, and the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, cos, sin = math.pi, math.cos, math.sin
local same = check.same_within(1e-9)

-- bilinear: corners, the mid point, partials, normal (Buimov §5.2)
local P00, P10, P01, P11 = P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 1)
local b = surface.bilinear(P00, P10, P01, P11)
eq(b.kind, "bilinear", "kind"); eq(b.dim, 3, "dim"); eq(b.u1, 1, "u1")
same(b(0, 0), P00, "corner 00"); same(b(1, 0), P10, "corner 10")
same(b(0, 1), P01, "corner 01"); same(b(1, 1), P11, "corner 11")
same(b(.5, .5), P(.5, .5, .25), "the middle: z = uv")
local S, Su, Sv = b:partials(.5, .5)
same(S, P(.5, .5, .25), "partials: the point"); same(Su, V(1, 0, .5), "dS/du"); same(Sv, V(0, 1, .5), "dS/dv")
same(b:normal(0, 0), V(0, 0, 1), "normal at the flat corner")

-- Bezier patch: its boundary iso-curves are the Bezier curves of the boundary rows
local net = {
  {P(0, 0, 0), P(0, 1, 1), P(0, 2, 0)},
  {P(1, 0, 1), P(1, 1, 2), P(1, 2, 1)},
  {P(2, 0, 0), P(2, 1, 1), P(2, 2, 0)},
}
local bz = surface.bezier(net)
local edge = bezier{net[1][1], net[1][2], net[1][3]}
for t = 0, 1, .25 do same(bz:iso("u", 0)(t), edge(t), "iso u = 0 is the first row's curve at " .. t) end
same(bz(.5, .5), P(1, 1, 1), "the middle of the symmetric net")
eq(bz:iso("v", .3).kind, "iso-curve", "an iso-curve is a curve")

-- B-spline patch of degrees 2, 2 on a 3 x 3 net with open knots is the Bezier patch
local bs = surface.bspline(net, 2, 2)
for _, uv in ipairs{{.1, .2}, {.5, .5}, {.9, .3}} do
  same(bs(uv[1], uv[2]), bz(uv[1], uv[2]), "B-spline = Bezier at " .. uv[1] .. ", " .. uv[2])
end

-- bicubic Hermite: corners and tangents reproduced (Buimov §5.5)
local h = surface.hermite{
  P = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0)},
  Pu = {V(1, 0, 1), V(1, 0, -1), V(1, 0, 0), V(1, 0, 0)},
  Pv = {V(0, 1, 0), V(0, 1, 0), V(0, 1, 0), V(0, 1, 0)},
  Puv = {V(0, 0, 0), V(0, 0, 0), V(0, 0, 0), V(0, 0, 0)},
}
same(h(1, 1), P(1, 1, 0), "Hermite corner"); local _, hu = h:partials(0, 0); same(hu, V(1, 0, 1), "Hermite u-tangent")

-- ruled, Coons and revolution from curves
local c0, c1 = bezier{P(0, 0, 0), P(1, 0, 0)}, bezier{P(0, 1, 1), P(1, 1, 1)}
local ru = surface.ruled(c0, c1)
same(ru(.3, 0), c0(.3), "ruled at v = 0"); same(ru(.3, 1), c1(.3), "ruled at v = 1")
local w = cos(pi / 4)
local arc = bezier{P(1, 0, 0), P(1, 1, 0) * w, P(0, 1, 0)}
local co = surface.coons(arc, bezier{P(1, 0, 1), P(1, 1, 1) * w, P(0, 1, 1)},
                         bezier{P(1, 0, 0), P(1, 0, 1)}, bezier{P(0, 1, 0), P(0, 1, 1)})
for t = 0, 1, .2 do same(co(t, 0), arc(t), "Coons reproduces its boundary at " .. t) end
near(dist(co(.37, .5), P(0, 0, .5)), 1, 1e-12, "a Coons quarter cylinder")
local prof = bezier{P(1, 0, 0), P(2, 0, 1), P(1, 0, 2)}
local rev = surface.revolution(prof, P(0, 0, 0), V(0, 0, 1))
for v = 0, 2 * pi, pi / 3 do
  local x = rev(.4, v)
  near(math.sqrt(x.x ^ 2 + x.y ^ 2), prof(.4).x, 1e-12, "radius kept at v = " .. v)
  near(x.z, prof(.4).z, 1e-12, "height kept")
end
same(rev(.7, 0), prof(.7), "v = 0 is the profile")
local iso = rev:iso("v", .5)
near(iso:length(), prof:length(), 1e-6, "a turned profile has the profile's length")

-- a Lua function; maps
local sph = surface(function(u, v) return P(cos(u) * cos(v), sin(u) * cos(v), sin(v)) end, 0, 2 * pi, -pi / 2, pi / 2)
same(sph(0, 0), P(1, 0, 0), "function surface"); same(sph:normal(0, 0), V(1, 0, 0), "outward normal", 1e-6)
local moved = map.translate(V(0, 0, 5))(b)
same(moved(.5, .5), P(.5, .5, 5.25), "f(surface)")
same(b:map(map.translate(V(1, 1, 1)))(0, 0), P(1, 1, 1), "s:map(f)")

-- wireframes: paths through the camera; hidden lines left out or dashed
local function ink(c)
  local n = 0
  for y = 0, 479, 1 do for x = 0, 639, 1 do if point(x, y) == c then n = n + 1 end end end
  return n
end
screen(12)
camera(map.translate(V(320, 240)) * map.scale({150, -150}) * map.axonometric(.5, .4))
sph:wireframe{nu = 12, nv = 8, color = 11}
local all = ink(11)
cls()
sph:wireframe{nu = 12, nv = 8, color = 11, hidden = "hide"}
local seen = ink(11)
cls()
sph:wireframe{nu = 12, nv = 8, color = 11, hidden = "dashed"}
local dashed = ink(11)
truthy(seen < all * .7 and seen > all * .35, "about half the sphere is hidden: " .. seen .. " of " .. all)
truthy(dashed > seen and dashed < all, "dashes draw part of the hidden lines: " .. dashed)
-- the front-most point of the equator is seen, the back-most is not
cls()
sph:wireframe{nu = 12, nv = 2, color = 11, hidden = "hide"}   -- the equator is the line v = 0
local f = camera()
local function px(p) local x, y = f:xy(p); return math.floor(x + .5), math.floor(y + .5) end
-- towards the viewer of a parallel projection onto the y-down screen: -(r1 x r2)
local m = f:matrix()
local toward = -cross(V(m[1][1], m[1][2], m[1][3]), V(m[2][1], m[2][2], m[2][3]))
local ufront = math.atan(toward.y, toward.x)
local function ink_near(x, y)   -- a steep path may pass a pixel beside the rounded point
  for dy = -1, 1 do for dx = -1, 1 do if point(x + dx, y + dy) == 11 then return true end end end
  return false
end
truthy(ink_near(px(sph(ufront, 0))), "the front of the equator is drawn")
truthy(not ink_near(px(sph(ufront + pi, 0))), "its back is hidden")
camera(nil)

-- errors ---------------------------------------------------------------------------------------
err(function() surface.bilinear(P(0, 0), P(1, 0), P(0, 1)) end, "argument #4 (P11)", "a missing corner")
err(function() surface.bilinear(P(0, 0), P(1, 0), P(0, 1), P(1, 1, 1)) end, "dimensions", "mixed dimensions")
err(function() surface.bezier({{P(0, 0)}}) end, "at least 2 rows", "too small a net")
err(function() surface.bezier({{P(0, 0), P(1, 0)}, {P(0, 1)}}) end, "row [2] holds 1 points", "ragged net")
err(function() surface.bezier({{P(0, 0), 3}, {P(0, 1), P(1, 1)}}) end, "[1][2] must be a point", "not a point")
err(function() surface.bezier({{P(0, 0), P(1, 0)}, 5}) end, "surface.bezier: argument #1 (net) row [2] must be a list of points, got 5", "a row that is no list")
err(function() surface.bezier({{P(0, 0), P(1, 0)}, {P(0, 1, 0), P(1, 1)}}) end,
    "surface.bezier: argument #1 (net) [2][1] is 3-D, but [1][1] is 2-D (mixed dimensions)", "mixed dimensions in row [2]")
err(function() surface.bspline(net, 3, 2) end, "argument #2 (p)", "degree too high")
err(function() surface.hermite{P = {P(0, 0, 0)}} end, "surface.hermite: option 'P' must hold 4 points, got 1", "Hermite corners")
err(function() surface.ruled(c0, 5) end, "argument #2 (c1)", "not a curve")
err(function() surface.coons(arc, arc, arc, arc) end, "do not meet at the corners", "Coons corners")
err(function() surface.revolution(prof, P(0, 0, 0), V(0, 0, 0)) end, "nonzero vector", "zero axis")
err(function() surface.revolution(bezier{P(0, 0), P(1, 1)}, P(0, 0, 0), V(0, 0, 1)) end, "3-D curve", "2-D profile")
err(function() surface(5, 0, 1, 0, 1) end, "argument #1 (f)", "not a function")
err(function() surface(function() return P(0, 0, 0) end, 1, 0, 0, 1) end, "u0 < u1", "empty domain")
err(function() sph(0 / 0, 0) end, "finite", "NaN parameter")
err(function() sph:iso("w", 0) end, "family", "bad iso family")
local far = surface.bezier{{P(0, 0), V(1, 0)}, {P(0, 1), P(1, 1)}}   -- (0, 1) a direction
err(function() far:partials(0, 1) end, "s:partials: the point at (0, 1) is at infinity",
    "partials at infinity")
err(function() sph:wireframe() end, "needs a projection", "3-D wireframe without a camera")
camera(map.isometric())
err(function() sph:wireframe{hidden = "maybe"} end, "s:wireframe: option 'hidden' must be \"show\", \"hide\" or \"dashed\", got \"maybe\"", "bad hidden mode")
err(function() sph:wireframe{nu = -1} end, "s:wireframe: option 'nu' must be an integer from 0 to 1000, got -1", "bad count")
err(function() sph:wireframe{hiden = "hide"} end, "s:wireframe: unknown option 'hiden' (did you mean 'hidden'?)", "a misspelt key")
err(function() sph:wireframe{colour = 99} end, "s:wireframe: option 'colour' must be a colour number 0..15 or \"#rrggbb\", got 99", "colour is color")
err(function() sph.wireframe{} end, "s:wireframe: must be called on a surface, as s:wireframe(...)", "a method called with a dot")
err(function() sph:iso("w", 0) end, "s:iso: argument #1 (family) must be \"u\" (u = const) or \"v\" (v = const), got \"w\"", "the family's message")
err(function() surface.bezier({{P(0, 0), P(1, 0)}, {P(0, 1), P(1, 1, 1)}}) end,
    "surface.bezier: argument #1 (net) [2][2] is 3-D, but [1][1] is 2-D (mixed dimensions)", "a net's dimensions")
err(function() surface.hermite{P = {P(0, 0), P(1, 0), P(0, 1), P(1, 1)}, Pu = {V(1, 0), V(1, 0), P(1, 0), V(1, 0)},
                               Pv = {V(0, 1), V(0, 1), V(0, 1), V(0, 1)}, Puv = {V(0, 0), V(0, 0), V(0, 0), V(0, 0)}} end,
    "surface.hermite: option 'Pu' [3] must be a 2-D vector, got P(1, 0)", "a Hermite tangent")
camera(nil)
err(function() surface.bilinear(P(0, 0), P(1, 0), P(0, 1), P(1, 1)):wireframe{hidden = "hide"} end,
    "3-D surface", "hidden lines of a plane patch")
local bad = surface(function(u, v) if u > .5 then error("surface boom") end return P(u, v, 0) end, 0, 1, 0, 1)
err(function() bad(.9, .1) end, "surface boom", "an error in f reaches the script")

check.done()
