-- The textbook's conics take the book's parameter (issue 24): plane.ellipse and plane.hyperbola
-- at parameters between the quarter turns, their tangents, and the circles' angles.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local near, truthy = check.near, check.truthy
local same = check.same_within(1e-12)

local e = plane.ellipse(P(1, 2), 3, 2)
same(e(1.0), P(2.620907, 3.682942), "plane.ellipse(P(1,2), 3, 2)(1.0)", 5e-7)
for _, th in ipairs{0.1, 0.5, 1.0, math.pi / 3, 2.5, 4, 5.9} do
  same(e(th), P(1 + 3 * math.cos(th), 2 + 2 * math.sin(th)), "ellipse at th = " .. th)
  same(e:deriv(th), V(-3 * math.sin(th), 2 * math.cos(th)), "its derivative", 1e-11)
end
same(e:tangent(math.pi / 3), unit(V(-3 * math.sin(math.pi / 3), 2 * math.cos(math.pi / 3))), "tangent at pi/3")
local h = plane.hyperbola(2, 1.5, -1.3, 1.3)
same(h(0.7), P(2.510338, 1.137876), "plane.hyperbola(2, 1.5, -1.3, 1.3)(0.7)", 5e-7)
for _, t in ipairs{-1.1, -0.3, 0.2, 0.7, 1.25} do
  same(h(t), P(2 * math.cosh(t), 1.5 * math.sinh(t)), "hyperbola at t = " .. t)
end
local c = plane.circle3(P(1, 1), P(2, 2), P(3, 2))
same(c.curve(1.0), c.centre + V(math.cos(1), math.sin(1)) * c.r, "circle3's curve at angle 1")
-- still the conic it is
local ce = e:conic()
near(ce.a, 3, 1e-9, "the ellipse's conic: a")
truthy(not ce.circle, "not a circle")
check.done()
