-- Affine maps through Lua: by point correspondences, frames, the oblique projection of
-- Stepanov's examples 32-34, application to points and vectors, composition, inverse, and
-- every error message of the affine binding.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, approx, err, truthy = check.eq, check.near, check.err, check.truthy

local same = check.same_within(1e-12)             -- points/vectors equal within tol

-- by three pairs in the plane ------------------------------------------------------------------------
local f = affine({P(0, 0), P(1, 0), P(0, 1)}, {P(2, 1), P(4, 2), P(1, 3)})
eq(tostring(f), "affine map 2-D -> 2-D [2 -1 | 2; 1 2 | 1]", "tostring shows [M | t]")
eq(getmetatable(f).__name, "map", "the one map type")
same(f(P(0, 0)), P(2, 1), "f(A) = A2"); same(f(P(1, 0)), P(4, 2), "f(B) = B2"); same(f(P(0, 1)), P(1, 3), "f(C) = C2")
same(f(V(1, 1)), V(1, 3), "vectors ignore the translation")
same(f(1, 1), P(3, 4), "f(x, y) takes coordinates")
eq(f(P(1, 0) * 2).w, 2, "weights are kept")
same(f(mid(P(0, 0), P(1, 1))), mid(f(P(0, 0)), f(P(1, 1))), "midpoints go to midpoints")
-- a general triangle onto another; any point's parameters are kept (change of simplex)
local S1 = {P(1, 1), P(5, 2), P(2, 4)}
local S2 = {P(0, 0), P(3, -1), P(7, 7)}
local g = affine(S1, S2)
for i = 1, 3 do same(g(S1[i]), S2[i], "pair " .. i) end
local M = (S1[2] - S1[1]) * 0.3 + (S1[3] - S1[1]) * 0.45 + S1[1]
same(g(M), (S2[2] - S2[1]) * 0.3 + (S2[3] - S2[1]) * 0.45 + S2[1], "the same natural parameters in the image", 1e-12)
-- simplices are accepted in place of tables
same(affine(simplex(S1[1], S1[2], S1[3]), S2)(M), g(M), "affine(simplex, table)")

-- composition and inverse ---------------------------------------------------------------------------------
local gi = g:inverse()
for _, X in ipairs({P(0, 0), P(3, -7), P(1e3, 2)}) do
  same((g * gi)(X), X, "g * g^-1 = id", 1e-9)
  same((gi * g)(X), X, "g^-1 * g = id", 1e-9)
end
same(g:compose(gi)(P(5, 5)), P(5, 5), "f:compose(g)", 1e-12)
local scale = affine.frame(P(0, 0), V(2, 0), V(0, 2))
local shift = affine.frame(P(1, 0), V(1, 0), V(0, 1))
same((scale * shift)(P(1, 1)), P(4, 2), "f * g applies g first")
same((shift * scale)(P(1, 1)), P(3, 2), "and then f")
-- 3-D by four pairs
local h = affine({P(1, 0, 0), P(2, 1, 0), P(1, 2, 1), P(0, 0, 3)}, {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0.5, 0.5, 1)})
same(h(P(0, 0, 3)), P(0.5, 0.5, 1), "3-D pair")
same(h:inverse()(P(0.5, 0.5, 1)), P(0, 0, 3), "3-D inverse", 1e-12)
eq(tostring(affine.identity(2)), "affine map 2-D -> 2-D [1 0 | 0; 0 1 | 0]", "identity")

-- frames and the oblique projection of Stepanov's examples 32-34 --------------------------------------
-- screen = C0 + x (C1 - C0) + y (C2 - C0) + z (C3 - C0), C0 = (320, 240), cr0 = 150, ck0 = .3, cu0 = -pi/3
local cr, ck, cu = 150, 0.3, -math.pi / 3
local C0 = P(320, 240)
local C1 = C0 + V(cr * math.cos(cu), -cr * ck * math.sin(cu))
local C2 = C0 + V(cr * math.cos(cu + math.pi / 2), -cr * ck * math.sin(cu + math.pi / 2))
local C3 = C0 + V(0, -cr)
local F = affine.frame(C0, C1, C2, C3)
local G = affine({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1)}, {C0, C1, C2, C3})
same(F(1, 0, 1), G(P(1, 0, 1)), "frame = map by four image points")
truthy(math.abs(F(1, 0, 1).x - 395) < 1 and math.abs(F(1, 0, 1).y - 129) < 1, "node (1,0,1) at screen (395,129) as in the article")
same(F(P(0, 0, -1)), C0 + V(0, cr), "the bottom node (…, -1) below the centre")
same(affine.frame(C0, C1 - C0, C2 - C0, C3 - C0)(P(1, 2, 3)), F(P(1, 2, 3)), "axes as vectors or as points")
eq(#F(P(1, 2, 3)), 2, "3-D to 2-D")
pset(F(P(1, 0, 0)), 14)
local sx, sy = coords(F(P(1, 0, 0)))
eq(point(math.floor(sx + 0.5), math.floor(sy + 0.5)), 14, "a projected point can be drawn")

-- errors ------------------------------------------------------------------------------------------------
err(function() return F:inverse() end, "inverse: a map from 3-D to 2-D (a projection or an embedding) has no inverse", "non-square")
err(function() return affine.frame(P(0, 0), V(1, 2), V(2, 4)):inverse() end, "inverse: the map is singular (it flattens space), so it has no inverse", "singular")
err(function() return affine({P(0, 0), P(1, 1), P(2, 2)}, {P(0, 0), P(1, 0), P(0, 1)}) end, "affine: the source points are collinear, so they do not fix an affine map", "collinear source")
err(function() return affine({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(1, 1, 0)}, {P(0, 0), P(1, 0), P(0, 1), P(1, 1)}) end, "affine: the source points are coplanar", "coplanar source")
err(function() return affine({P(0, 0), P(1, 1)}, {P(0, 0), P(1, 0)}) end, "affine: argument #1 (source points) holds 2 2-D points; a map of 2-D needs 3 (dimension + 1)", "too few pairs")
err(function() return affine({P(0, 0), P(1, 0), P(0, 1)}, {P(0, 0), P(1, 0)}) end, "affine: argument #2 (image points) holds 2 points, argument #1 3: they must pair up", "unpaired")
err(function() return affine({P(0, 0), P(1, 0), P(0, 1, 0)}, {P(0, 0), P(1, 0), P(0, 1)}) end, "affine: argument #1 (source points) [3] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed source")
err(function() return affine({P(0, 0), 5, P(0, 1)}, {P(0, 0), P(1, 0), P(0, 1)}) end, "affine: argument #1 (source points) [2] must be a point, got 5", "non-point item")
err(function() return affine({P(0, 0), V(1, 0), P(0, 1)}, {P(0, 0), P(1, 0), P(0, 1)}) end, "affine: argument #1 (source points) [2] must be a point, got V(1, 0); a point has weight 1: to place a vector, add it to a point, e.g. P(0, 0) + v", "vector item")
err(function() return affine(5, {}) end, "affine: argument #1 (source points) must be a table of points or a simplex, got 5", "not a table")
err(function() return affine({P(0, 0), P(1, 0), P(0, 1)}) end, "affine: argument #2 (image points) must be a table of points or a simplex, got nil", "no images")
err(function() return affine({}, {}) end, "affine: argument #1 (source points) holds 0 points; a map of n-D needs n + 1 (3 in the plane, 4 in space)", "empty source")
err(function() return f(P(1, 2, 3)) end, "f: argument #1 is 3-D, but the map takes 2-D: dimensions cannot be mixed", "apply dims")
err(function() return f(1) end, "f: takes a 2-D point or vector, or 2 coordinates; got number", "apply one number")
err(function() return f("x", 2) end, "f: takes a 2-D point or vector, or 2 coordinates; got string", "apply string")
err(function() return f(1, 0/0) end, "f: argument #2 must be a finite number, got ", "apply NaN")
err(function() return f(1, -math.huge) end, "f: argument #2 must be a finite number, got -inf", "apply -inf")
err(function() return f(1, "2") end, "f: argument #2 must be a finite number, got \"2\"", "apply: no string coercion")
err(function() return f(P(1, 2), P(3, 4)) end, "f: takes one point or vector, got 2 arguments", "apply two points")
err(function() return f * 2 end, "cannot multiply an affine map by a number: f * g composes two maps, and f(p) applies one", "map * number")
err(function() return F * F end, "cannot compose: the first map applied gives 2-D, the second takes 3-D", "compose dims")
err(function() return f:compose(3) end, "compose: argument #1 (g) must be a map, got 3", "compose arg")
err(function() return f.inverse(3) end, "inverse: must be called on a map, as f:inverse(...)", "bad self")
err(function() return affine.frame(P(0, 0)) end, "frame: argument #2 (X) must be a point or vector, got nil", "frame without axes")
err(function() return affine.frame(P(0, 0), P(1, 0, 0)) end, "affine.frame: argument #2 (X) is 3-D, but argument #1 (O) is 2-D (mixed dimensions)", "frame dims")
err(function() return affine.frame(P(0, 0), P(1, 0) * 2) end, "affine.frame: argument #2 (X) must be a point or vector, got 2*P(1, 0); its weight is 2, and a point equation's coefficients sum to 1 for a point, 0 for a vector (the membership condition)", "frame weighted axis")
err(function() return affine.identity(0) end, "affine.identity: argument #1 (n) must be an integer from 1 to 16, got 0", "identity")

-- the drawing was only a check: save it to a scratch file so the host does not write one
local scratch = os.tmpname()
save(scratch .. ".ppm")
os.remove(scratch .. ".ppm"); os.remove(scratch)

check.done()
