-- The textbook's perspective by (p, q, r), foreshortening of any axonometry, the axial affinity
-- (issue 24; digest buimov_textbook.md §2.8.3-§2.8.5, checks 15-17).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err = check.eq, check.near, check.err
local same = check.same_within(1e-12)

local f = map.perspective_pqr(0, 0, 0.5)
same(f(V(0, 0, 1)), P(0, 0, 2), "one-point: the vanishing point (0, 0, 1/r)")
same(map.perspective_pqr(0.5, 0.5, 0)(P(1, 0, 1)), P(2 / 3, 0, 2 / 3), "two-point: (1, 0, 1)")
same(map.perspective_pqr(0.5, 0.5, 0.5)(P(1, 1, 1)), P(0.4, 0.4, 0.4), "three-point: (1, 1, 1)")
-- the perspective then a parallel projection composes as any two maps
local pic = map.orthographic("z") * map.perspective_pqr(0, 0, 0.5)
same(pic(P(1, 1, 1)), P(2 / 3, 2 / 3), "then onto z = 0: (2/3, 2/3)")
local fx, fy, fz = map.foreshortening(map.dimetric(0.5))
near(fx, math.sqrt(7 / 8), 1e-12, "dimetric f_x = sqrt(7/8)")
near(fy, math.sqrt(7 / 8), 1e-12, "f_y")
near(fz, 0.5, 1e-12, "f_z = 1/2")
local phi, theta = math.rad(30), math.rad(15)              -- a trimetric
local tx, ty, tz = map.foreshortening(map.axonometric(phi, theta))
near(tx, math.sqrt(math.cos(phi) ^ 2 + math.sin(phi) ^ 2 * math.sin(theta) ^ 2), 1e-12, "trimetric f_x")
near(ty, math.cos(theta), 1e-12, "f_y = cos theta")
near(tz, math.sqrt(math.sin(phi) ^ 2 + math.cos(phi) ^ 2 * math.sin(theta) ^ 2), 1e-12, "f_z")
local g = map.axial_affinity(P(0, 0), V(1, 0), V(0, 1), 2)
same(g(P(3, 4)), P(3, 8), "the affinity doubles the distance from the axis")
local r = map.axial_affinity(P(0, 0), V(1, 0), V(1, 1), -1)
same(r(P(0, 1)), P(-2, -1), "an oblique reflection")
same(r(r(P(0.3, 0.7))), P(0.3, 0.7), "which is its own inverse")
err(function() map.foreshortening(f) end, "map.foreshortening: a perspective (projective) map has no constant foreshortening", "perspective")
err(function() map.axial_affinity(P(0, 0), V(1, 0), V(2, 0), 2) end, "map.axial_affinity: the direction s lies along the axis d", "s along d")
err(function() map.axial_affinity(P(0, 0), P(1, 0), V(2, 0), 2) end, "map.axial_affinity: argument #2 (d) must be a 2-D vector", "a point for d")
check.done()
