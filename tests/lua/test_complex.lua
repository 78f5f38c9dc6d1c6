-- Complex numbers and the Moebius map of the disc (examples 15, 16 of stepanov_examples.md).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy

local z, w = complex(1, 2), complex(3, -1)
eq(tostring(z), "complex(1, 2)", "tostring"); eq(z.re, 1, "re"); eq(z.im, 2, "im")
eq(z + w, complex(4, 1), "+"); eq(z - w, complex(-2, 3), "-"); eq(z * w, complex(5, 5), "*")
eq(z / complex(0, 1), complex(2, -1), "/"); eq(-z, complex(-1, -2), "unary -")
eq(z * 2, complex(2, 4), "complex * number"); eq(1 + z, complex(2, 2), "number + complex")
eq(2 / complex(0, 2), complex(0, -1), "number / complex")
eq(z ^ 2, complex(-3, 4), "integer power"); eq(z ^ -1, 1 / z, "negative power")
eq(complex.i * complex.i, complex(-1, 0), "i^2 = -1")
eq(z:conj(), complex(1, -2), "conj"); near(z:abs(), math.sqrt(5), 1e-15, "abs")
near(complex(0, 1):arg(), math.pi / 2, 1e-15, "arg")
local e = complex.exp(complex(0, math.pi))
near(e.re, -1, 1e-15, "e^(i pi) re"); near(e.im, 0, 1e-15, "e^(i pi) im")
local p = complex.polar(2, math.pi / 3)
near(p.re, 1, 1e-15, "polar re"); near(p.im, math.sqrt(3), 1e-15, "polar im")
eq(complex(P(3, 4)), complex(3, 4), "complex(P)"); eq(complex(3, 4):point(), P(3, 4), "z:point()")
eq(complex(5), complex(5, 0), "complex(re)")
err(function() return z / 0 end, "complex /: division by zero", "division by zero")
err(function() return z + "a" end, "complex +: argument #2 (right) must be a complex number or a number, got string", "z + string")
err(function() complex("a") end, "complex: argument #1 (re) must be a number or a 2-D point, got string", "complex(string)")

-- example 15: z0 = r0 e^(i u0), r0 = 1/2, u0 = pi/4, phi = 0
local M = mobius(complex.polar(.5, math.pi / 4))
local w0 = M(M.z0)
near(w0:abs(), 0, 1e-15, "z0 goes to 0")
local o = M(0)
near(320 + 200 * o.re, 249.3, .05, "0 goes to -z0: screen x 249"); near(240 - 200 * o.im, 310.7, .05, "screen y 311")
local x, y = M(.3, .4)
local q = M(complex(.3, .4))
near(x, q.re, 0, "M(x, y) = M(z) re"); near(y, q.im, 0, "M(x, y) = M(z) im")
eq(M(P(.3, .4)), P(q.re, q.im), "M(P) is a point")
local Mi = mobius(complex.polar(.5, math.pi / 4), 1.1)
local inv = Mi:inverse()
for r = 0, 1, .25 do
  for u = 0, 6.2, .7 do
    local zz = complex.polar(r, u)
    local ww = Mi(zz)
    if r == 1 then near(ww:abs(), 1, 1e-12, "the circle onto the circle")
    else truthy(ww:abs() < 1, "the disc into the disc") end
    local back = inv(ww)
    near(back.re, zz.re, 1e-12, "inverse re"); near(back.im, zz.im, 1e-12, "inverse im")
  end
end
near(Mi.phi, 1.1, 0, "M.phi")
truthy(tostring(M):find("^mobius%(complex%(0.35355339059327, 0.35355339059327%), 0%)"), "tostring")
err(function() mobius(complex(1, 0)) end, "mobius: argument #1 (z0) must be a point inside the unit disc (|z0| < 1)", "|z0| = 1")
err(function() mobius(.5)(2, 0) end, "is the pole 1/conj(z0) of the map", "pole")
err(function() M("a") end, "must be a complex number, a 2-D point or x, y, got string", "M(string)")
check.done()
