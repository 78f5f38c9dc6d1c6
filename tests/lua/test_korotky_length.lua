-- korotky.elastic{length =} (issue 24): the fixed-length elastic line for the clamped
-- experiment of Korotky & Vitovtov (2021); and the 4-D planking of Korotky (2015), Fig. 1c.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, truthy, err = check.eq, check.near, check.truthy, check.err

local pts = {P(1.2, .9), P(2.1, 2.3), P(2.8, 4), P(5, 3.2), P(5.5, 2.1)}   -- Table A1
local clamped = {0.2, 5.16, 0.83, -4.36, -0.3}                              -- Table A4
local function worst_angle(c, meas)   -- the largest angle from the measured slopes at B, C, D
  local w = 0
  for i = 1, 3 do
    local d = c:deriv(i)
    w = math.max(w, math.abs(math.deg(math.atan(d.y / d.x) - math.atan(meas[i + 1]))))
  end
  return w
end

-- free length: the slopes at B, C, D are 5 degrees off Table A4 (the digest's 5.0)
local c0, E0 = korotky.elastic(pts, {ends = {.2, -.3}})
local L0 = c0:length()
truthy(worst_angle(c0, clamped) > 4, "free length: more than 4 degrees from Table A4")
-- the length 7.70 (shorter than the free minimum's 7.89) meets the measured slopes within 1.1
-- degrees: the clamped ruler's length, which the article does not give, is about 7.7 units
local c, E = korotky.elastic(pts, {ends = {.2, -.3}, length = 7.70})
near(c:length(), 7.70, 1e-5, "the length is met")
truthy(E > E0, "a length other than the free minimum's costs energy")
truthy(worst_angle(c, clamped) < 1.1, "length 7.70: within 1.1 degrees of Table A4")
for i = 1, 5 do near(dist(c(i - 1), pts[i]), 0, 1e-12, "through pin " .. i) end
local dA, dE = c:deriv(0), c:deriv(4)
near(dA.y / dA.x, .2, 1e-12, "clamped at A")
near(dE.y / dE.x, -.3, 1e-12, "clamped at E")
local dk = korotky.joint_jumps(c)
truthy(dk < 1e-9, "curvature continuous at the pins")
-- the compressed ruler (Table A5) with its own length 5.51: within 1.3 degrees
local low = {}
for i, p in ipairs(pts) do low[i] = P(p.x, p.y / 2) end
local cl = korotky.elastic(low, {ends = {.1, -.15}, length = 5.51})
truthy(worst_angle(cl, {0.1, 1.528, 0.721, -1.481, -0.15}) < 1.3, "compressed, length 5.51: within 1.3 degrees of Table A5")
-- the free-length minimum's own length gives the free curve back
local f0, F0 = korotky.elastic(pts)
local f1, F1 = korotky.elastic(pts, {length = f0:length()})
near(F1, F0, 1e-5, "the free minimum's length: the same energy")
near(F0, 1.8188, 2e-4, "the digest's energy")

-- errors name the call and the option
err(function() korotky.elastic(pts, {length = 7}) end, "not longer than the polyline", "too short")
err(function() korotky.elastic(pts, {length = -1}) end, "option 'length' must be a positive number", "negative")
err(function() korotky.elastic(pts, {length = "long"}) end, "option 'length'", "not a number")
err(function() korotky.elastic(pts, {lenght = 7.7}) end, "length", "misspelt key: did you mean")

-- Fig. 1c, the planking: the longitudinal generators MN are plane conics, and in xyt each
-- station is a straight ruling of the conoid (plane of parallelism xt)
local L, xC, zA, zB, zD, zC = 5, 1.4, .4, 1.2, 0, 1.1
local plan = korotky.conic_arc(P(0, 0), V(1, 1.6), P(xC, L), V(0, 1), P(1.05, 2.2))
local BC = curve(function(u) local q = plan(u); return P(q.x, q.y, zB + (zC - zB) * q.y / L, 1) end, 0, 1)
local AD = curve(function(u) return P(0, plan(u).y, zA + (zD - zA) * plan(u).y / L, 0) end, 0, 1)
local AB = curve(function(v) return P(0, 0, zA + (zB - zA) * v, v) end, 0, 1)
local CD = curve(function(v) return P(xC * v, L, zD + (zC - zD) * (1 - (1 - v)^2), v) end, 0, 1)
local hull = korotky.two_pencils{omega = {BC, AD, V(0, 0, 1, 0)}, delta = {V(1, 0, 0, 0), AB, CD}}
near(dist(hull(0, .3), AB(.3)), 0, 1e-9, "the frame AB at u = 0")
near(dist(hull(1, .7), CD(.7)), 0, 1e-9, "the frame CD at u = 1")
local v = .6
local M = {}
for i = 0, 5 do M[i + 1] = hull(i / 5, v) end
-- in one plane: z is a linear function of y along MN
local a = (M[6].z - M[1].z) / (M[6].y - M[1].y)
for i = 2, 5 do near(M[i].z, M[1].z + a * (M[i].y - M[1].y), 1e-9, "MN plane, point " .. i) end
-- its plan is a conic: the conic through five of its points holds the sixth
local k = conic.elements(P(M[1].x, M[1].y), P(M[2].x, M[2].y), P(M[3].x, M[3].y),
                         P(M[4].x, M[4].y), P(M[5].x, M[5].y)).coef
local x, y = M[6].x, M[6].y
local scale = math.abs(k[1]) + math.abs(k[2]) + math.abs(k[3]) + math.abs(k[4]) + math.abs(k[5]) + math.abs(k[6])
near((k[1] * x * x + k[2] * x * y + k[3] * y * y + k[4] * x + k[5] * y + k[6]) / scale, 0, 1e-9, "MN is a conic")
-- xyt: the station u = 0.4 is a straight line (x, t linear in each other, y fixed)
local R = {}
for i = 0, 4 do R[i + 1] = hull(.4, i / 4) end
for i = 2, 4 do
  near(R[i].y, R[1].y, 1e-9, "a station keeps y")
  local s = (R[i][4] - R[1][4]) / (R[5][4] - R[1][4])
  near(R[i].x, R[1].x + s * (R[5].x - R[1].x), 1e-9, "the conoid's ruling is straight in xyt")
end
check.done()
