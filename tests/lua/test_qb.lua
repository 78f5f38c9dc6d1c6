-- The qb table: QBasic's number semantics for Lua scripts (SINGLE rounding, CINT, RND, the
-- FOR loop accumulating in float32), and the QBasic translator reachable from Lua.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- f32: binary32 rounding
check.eq(qb.f32(0.5), 0.5, "f32 exact")
check.eq(qb.f32(0.1), 0.10000000149011612, "f32(.1)")
check.eq(qb.f32(4 * math.atan(1)), 3.1415927410125732, "f32(pi)")
check.eq(qb.f32(16777217), 16777216.0, "f32 of 2^24 + 1")
check.eq(qb.f32(-1e39), -math.huge, "f32 beyond the SINGLE range is -inf (documented)")
check.eq(qb.csng(0.1), 0.10000000149011612, "csng(.1) is f32(.1)")
check.eq(qb.csng(-3.4e38), qb.f32(-3.4e38), "csng inside the SINGLE range")
check.err(function() qb.csng(1e39) end, "Overflow", "csng beyond the SINGLE range")
check.err(function() qb.csng(0 / 0) end, "Overflow", "csng of NaN")

-- cint/clng: ties to even, overflow flag
local v, ok = qb.cint(2.5)
check.eq(v, 2, "cint(2.5)"); check.eq(ok, true, "cint ok")
check.eq(math.type(v), "integer", "cint returns an integer")
check.eq((qb.cint(3.5)), 4, "cint(3.5)")
check.eq((qb.cint(-2.5)), -2, "cint(-2.5)")
v, ok = qb.cint(32767.5)
check.eq(ok, false, "cint overflow")
v, ok = qb.clng(70000.5)
check.eq(v, 70000, "clng(70000.5)"); check.eq(ok, true, "clng ok")

-- RND: QBasic's sequence, RND(0), reseeding, the seed
qb.seed(327680)
local want = { 0.7055475, 0.533424, 0.5795186, 0.2895625, 0.301948 }
local last
for i = 1, 5 do
  last = qb.rnd(1)
  check.near(last, want[i], 5e-8, "RND #" .. i)
end
check.eq(qb.rnd(0), last, "RND(0) repeats")
check.eq(qb.seed(), 5065847, "the seed after five values")
qb.seed(327680)
check.eq(qb.rnd(), 11837123 / 16777216, "RND() is RND(1)")
check.eq(qb.rnd(-1), 3758214 / 16777216, "RND(-1) reseeds from the SINGLE bits")
check.eq(qb.rnd(-1), 3758214 / 16777216, "RND(-1) again")
qb.seed(327680)
qb.randomize(1)
check.eq(qb.seed(), 0x3FF000, "RANDOMIZE 1")
check.err(function() qb.seed(2 ^ 24) end, "seed", "seed out of range")

-- arguments are checked in the house style, naming the argument and what is wrong
check.err(function() qb.f32() end, "qb.f32: argument #1 (x) must be a number, got nil", "f32()")
check.err(function() qb.cint("x") end, "qb.cint: argument #1 (x) must be a number, got \"x\"",
  "cint of a string")
check.err(function() qb.clng({}) end, "qb.clng: argument #1 (x) must be a number, got table", "clng of a table")
check.err(function() qb.rnd("x") end, "qb.rnd: argument #1 (n) must be a number, got \"x\"",
  "rnd of a string")
check.err(function() qb.randomize() end, "qb.randomize: argument #1 (n) must be a finite number, got nil",
  "randomize()")
check.err(function() qb.randomize(1 / 0) end, "qb.randomize: argument #1 (n) must be a finite number, got inf",
  "randomize(inf)")
check.err(function() qb.seed(1.5) end, "qb.seed: argument #1 (s) must be an integer from 0 to 16777215, got 1.5",
  "seed(1.5)")

-- range: the float32 FOR loop of QBasic
local n, lastt = 0, nil
for t in qb.range(0, 1, .001) do n = n + 1; lastt = t end
check.eq(n, 1001, "FOR t = 0 TO 1 STEP .001 runs 1001 times")
check.eq(lastt, qb.f32(0.9999907), "last value 0.9999907")
n = 0
for _ in qb.range(.2, 1.6, .2) do n = n + 1 end
check.eq(n, 7, "FOR r = .2 TO 1.6 STEP .2 runs 7 times")
n = 0
for _ in qb.range(0, 1, .0001) do n = n + 1 end
check.eq(n, 10000, "step .0001 runs 10000 times")
n = 0
for i in qb.range(10, 1, -3) do n = n + i end
check.eq(n, 10 + 7 + 4 + 1, "negative step")
n = 0
for _ in qb.range(1, 3) do n = n + 1 end
check.eq(n, 3, "default step 1")
for _ in qb.range(1, 0) do error("an empty loop ran") end
check.err(function() qb.range(0, 1, 0) end, "step", "zero step")
check.err(function() qb.range(0, "x") end, "qb.range: argument #2 (limit) must be a finite number, got \"x\"", "bad limit")
check.err(function() qb.range(0, 1, 1e-50) end, "qb.range: argument #3 (step) must be non-zero (in SINGLE), got 1e-50", "a step SINGLE rounds to 0")
check.eq(qb.f32(1 / 0), 1 / 0, "f32 keeps inf (SINGLE overflow)")
check.truthy(qb.f32(0 / 0) ~= qb.f32(0 / 0), "and NaN")
check.eq(qb.f32("0.5"), 0.5, "a numeric string is a number, as Lua converts it")

-- the translator from Lua: translate returns Lua text, or nil and "chunk:line: message"
local qbasic = require "qbasic"
local text = qbasic.translate("x = 1\nFOR i = 1 TO 3\nx = x * 2\nNEXT\n", "t.bas")
check.truthy(text and text:find("x = csng(x * 2)", 1, true), "translation")
local none, msg = qbasic.translate("x = 1\nNEXT i\n", "t.bas")
check.eq(none, nil, "bad program")
check.eq(msg, "t.bas:2: NEXT without FOR", "translation error message")

check.done()
