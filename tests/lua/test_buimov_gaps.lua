-- The textbook's API gaps of issue 24: buimov.spline with the user's segment lengths, the
-- sphere frame (tangents, twist, normal) at a general centre.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-12)

local pts = {P(0, 0), P(1, 2), P(3, 3), P(4, 0)}
local c = buimov.spline(pts, {lengths = {1, 2.5, 0.5}})
local u = {0, 1, 3.5, 4}
for j = 1, 4 do same(c(u[j]), pts[j], "node " .. j .. " at the accumulated length " .. u[j]) end
for _, t in ipairs{1, 3.5} do
  same(c:deriv(t, 2, "left"), c:deriv(t, 2, "right"), "C2 at the joint " .. t, 1e-9)
end
local cl = buimov.spline(pts, {ends = "clamped", d0 = V(1, 1), d1 = V(1, -1), lengths = {1, 2.5, 0.5}})
same(cl:deriv(0), V(1, 1), "clamped with lengths: the start tangent")
same(buimov.spline(pts, {lengths = {1, 1, 1}})(1.7), buimov.spline(pts)(1.7), "unit lengths = the book's uniform")
err(function() buimov.spline(pts, {lengths = {1, 2}}) end, "buimov.spline: option 'lengths' must hold 3 segment lengths", "count")
err(function() buimov.spline(pts, {lengths = {1, 0, 2}}) end, "buimov.spline: option 'lengths' [2] must be a positive length", "zero")
err(function() buimov.spline(pts, {lengths = {1, 1, 1}, param = "chord"}) end, "buimov.spline: give the parameter as param or as lengths, not both", "both")
-- the sphere frame at a general centre: S = C + r S1, the twist r times, N r^2 times
local C, r = P(1, -2, 0.5), 2.5
local S, St, Sp, tw, N = buimov.sphere_frame(0.4, 1.1, C, r)
local S1, St1, Sp1, tw1, N1 = buimov.sphere_frame(0.4, 1.1)
same(S, C + (S1 - P(0, 0, 0)) * r, "S = C + r S1")
same(tw, tw1 * r, "the twist")
same(N, N1 * (r * r), "N = S_th x S_ph")
same(N, cross(St, Sp), "N is the cross product")
near(dist(S, C), r, 1e-12, "on the sphere")
local s = buimov.sphere(0, 2 * math.pi, 0, math.pi, C, r)
same(s(0.4, 1.1), S, "the surface's point")
err(function() buimov.sphere_frame(0.4, 1.1, C, -1) end, "buimov.sphere_frame: argument #4 (r) must be a positive number", "r < 0")
check.done()
