-- slider(): a script's declared parameters (docs/live.md): defaults, values set by the host,
-- the list of declarations, and the argument errors.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, err, truthy = check.eq, check.err, check.truthy
local tk = _tk or require("pointcalc")._tk

eq(slider("k", 0, 1, .5), .5, "the default when nothing is set")
tk.param_set("r", 2.5)
eq(slider("r", 1, 3, 2), 2.5, "the value the host set")
eq(slider("k", 0, 1, .5), .5, "asking again")
eq(slider("t", 0, 6.25, 0, {step = .25, animate = true}), 0, "with options")
local decl = tk.params()
eq(#decl, 3, "three sliders declared, once each")
eq(decl[1].name, "k", "in order: k"); eq(decl[2].name, "r", "r"); eq(decl[3].name, "t", "t")
eq(decl[2].min, 1, "min kept"); eq(decl[2].max, 3, "max"); eq(decl[2].default, 2, "default")
eq(decl[3].step, .25, "step"); truthy(decl[3].animate, "animate"); truthy(not decl[1].animate, "not animated")
tk.param_set("q", 7)
err(function() slider("q", 0, 1, 0) end, "slider: the value 7 set for q is outside its range [0, 1]", "out of range")
err(function() slider(5, 0, 1, 0) end, "slider: argument #1 (name)", "a number as the name")
err(function() slider("a b", 0, 1, 0) end, "argument #1 (name)", "a blank in the name")
err(function() slider("a", 1, 0, 0) end, "argument #3 (max) must be greater than min", "empty range")
err(function() slider("a", 0, 1, 2) end, "argument #4 (default) must be between min and max", "default outside")
err(function() slider("a", 0, 1, 0 / 0) end, "argument #4 (default)", "NaN default")
err(function() slider("a", 0, 1, 0, -1) end, "argument #5 (step)", "negative step")
err(function() slider("a", 0, 1, 0, "x") end, "slider: argument #5 (step) must be a number or a table {step =, animate =}, got \"x\"", "bad step")
err(function() slider("a", 0, 1, 0, {stpe = .1}) end, "slider: unknown option 'stpe' (did you mean 'step'?)", "a misspelt key")
err(function() slider("a", 0, 1, 0, {animate = "yes"}) end, "slider: option 'animate' must be a boolean, got \"yes\"", "animate's kind")
err(function() slider("a", 0, 1, 0, 1 / 0) end, "slider: argument #5 (step) must be a number or a table {step =, animate =}, got inf", "an infinite step")
err(function() slider("a", 0, 1, 0, {1}) end, "slider: argument #5 (step) holds [1]; its options are named (key = value)", "a positional entry")
err(function() slider("a", 0, 1, 0, {step = 1 / 0}) end, "slider: option 'step' must be a finite number, got inf", "an infinite step in the table")
err(function() assert(pcall(slider, "a b", 0, 1, 0)) end, "slider: argument #1 (name) must be a name of letters, digits and _ (up to 64), got \"a b\"", "pcall names slider")
eq(slider("s", 0, 1, .5, .1), .5, "the short form: step alone")
local rec = {}
for _, d in ipairs(tk.params()) do rec[d.name] = d end
eq(rec.s.step, .1, "its step recorded")
check.done()
