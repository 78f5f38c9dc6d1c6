-- The help registry (interp/help.lua) against the real API: every function of the pointcalc
-- module has an entry, every entry names something that exists, the REPL's commands and the
-- methods of points, simplices and maps are all documented, and each entry is well formed.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local help = require "help"
local repl = require "repl"

local problems = {}
local function problem(fmt, ...)
  problems[#problems + 1] = string.format(fmt, ...)
end

-- every public value of the module (recursively through its tables), by dotted name
local function callable(v)
  local mt = debug.getmetatable(v)
  return type(v) == "function" or (type(mt) == "table" and rawget(mt, "__call") ~= nil)
end

local seen = {}
local function walk(t, prefix)
  for k, v in pairs(t) do
    if type(k) == "string" and (k:sub(1, 1) ~= "_" or k == "_VERSION") then
      local name = prefix .. k
      if type(v) == "table" and not seen[v] then
        seen[v] = true
        if callable(v) and not help.by_name[name] then
          problem("pointcalc.%s is callable but has no entry in interp/help.lua", name)
        end
        walk(v, name .. ".")
      elseif type(v) ~= "table" and not help.by_name[name] then
        problem("pointcalc.%s (a %s) has no entry in interp/help.lua: add def(%q, SIGNATURE, DESCRIPTION) to its area",
                name, type(v), name)
      end
    end
  end
end
walk(pointcalc, "")

-- every function or value entry names a field of the module
for _, e in ipairs(help.entries) do
  if e.kind == "function" or e.kind == "value" then
    local v = pointcalc
    for part in e.name:gmatch("[^.]+") do v = type(v) == "table" and rawget(v, part) or nil end
    if v == nil then
      problem("help entry %q names nothing in the pointcalc module (stale or misspelt)", e.name)
    end
  end
  if type(e.desc) ~= "string" or e.desc == "" or e.desc:find("\n") then
    problem("help entry %q: the description must be one non-empty line", e.name)
  end
  for _, form in ipairs(help.forms(e)) do
    if type(form) ~= "string" or form == "" then problem("help entry %q: empty signature", e.name) end
  end
  if not help.areas[e.area] then problem("help entry %q: unknown area %q", e.name, tostring(e.area)) end
end

-- the REPL's commands and the registry's area "repl" are the same set
local documented = {}
for _, e in ipairs(help.areas.repl.entries) do
  documented[e.name] = true
  if not repl.commands[e.name:sub(2)] then problem("help entry %q: the REPL has no such command", e.name) end
end
for name in pairs(repl.commands) do
  if not documented[":" .. name] then problem("REPL command :%s has no entry in interp/help.lua", name) end
end

-- methods: the tables that the values' __index functions hold (what Tab completes)
local function methods_of(v)
  local names = {}
  local mt = debug.getmetatable(v)
  local index = mt and rawget(mt, "__index")
  if type(index) == "table" then
    for k, f in pairs(index) do if type(f) == "function" then names[#names + 1] = k end end
  elseif type(index) == "function" then
    for i = 1, 8 do
      local _, up = debug.getupvalue(index, i)
      if type(up) == "table" and up ~= mt then
        for k, f in pairs(up) do if type(f) == "function" then names[#names + 1] = k end end
      end
    end
  end
  table.sort(names)
  return names
end

local point_methods = table.concat(help.forms(help.by_name["p:method"]), " ")
for _, m in ipairs(methods_of(P(1, 2))) do
  if not point_methods:find("p:" .. m .. "(", 1, true) then
    problem("point method p:%s is not listed in the help entry \"p:method\"", m)
  end
end
for _, sample in ipairs({{"S", simplex(P(0, 0), P(1, 0), P(0, 1))}, {"f", affine.identity(2)}}) do
  for _, m in ipairs(methods_of(sample[2])) do
    if not help.by_name[sample[1] .. ":" .. m] then
      problem("method %s:%s has no entry in interp/help.lua", sample[1], m)
    end
  end
end

check.eq(#problems, 0, "help registry problems:\n  " .. table.concat(problems, "\n  ") .. "\n")

-- :help NAME finds entries by their names, and commands with or without the colon
check.eq(help.find("lerp").area, "points", "lerp is point calculus")
check.eq(help.find("circle").area, "draw", "circle is drawing")
check.eq(help.find("show").name, ":show", "show finds :show")
check.truthy(help.find("qb.rnd"), "qb.rnd")

-- what the REPL prints for values
check.eq(repl.results(P(1, 2)), "P(1, 2)", "a point prints as P(1, 2)")
check.eq(repl.results(V(0, 1)), "V(0, 1)", "a vector prints as V(0, 1)")
check.eq(repl.results({1, 2, 3}), "table: 3 items {1, 2, 3}", "a short list")
check.eq(repl.results({}), "table: empty {}", "an empty table")
check.eq(repl.results({x = 1, y = "a"}), 'table: 2 items {x = 1, y = "a"}', "a record")
check.eq(repl.results(1, "two", nil), "1\ttwo\tnil", "several results, tab-separated")
check.eq(repl.results(), nil, "no results print nothing")
local big = {}
for i = 1, 100000 do big[i] = i end
local text = repl.results(big)
check.eq(text, "table: 100000 items {1, 2, 3, 4, 5, 6, 7, 8, ...}", "a huge table is summarised")
check.truthy(repl.results(lerp):find("lerp(A, B, t)", 1, true), "a documented function shows its signature")
fl = lerp   -- a user's shorter alias must not hide the documented name
check.truthy(repl.results(lerp):find("^function lerp%(A, B, t%)"), "an aliased function keeps its signature")
check.truthy(repl.results(fl):find("^function lerp%(A, B, t%)"), "the alias shows the documented function")
fl = nil
check.truthy(repl.results({P(1, 2), {1}}) == "table: 2 items {P(1, 2), {...}}", "nested values are brief")

-- completion candidates (repl.complete(text, line_before_text))
local function has(list, want)
  if type(list) ~= "table" then return false end
  for _, v in ipairs(list) do if v == want then return true end end
  return false
end
check.truthy(has(repl.complete("ler", ""), "lerp"), "a global name")
check.truthy(has(repl.complete("fun", ""), "function"), "a keyword")
check.truthy(has(repl.complete("qb.rn", "x = "), "qb.rnd"), "a field after '.'")
check.truthy(has(repl.complete("string.up", ""), "string.upper"), "a library function")
Pt = P(3, 4)
check.truthy(has(repl.complete("Pt.", ""), "Pt.x"), "a point's coordinate")
check.truthy(not has(repl.complete("Pt.", ""), "Pt.z"), "no .z for a 2-D point")
check.truthy(has(repl.complete("Pt:un", ""), "Pt:unit("), "a point's method after ':'")
check.truthy(not has(repl.complete("Pt:", ""), "Pt:x"), "':' offers methods only")
check.truthy(has(repl.complete(":sh", ""), ":show "), "a REPL command")
check.truthy(has(repl.complete("le", ":help "), "lerp"), "a help topic")
check.eq(repl.complete("ex", ":load "), "files", "file names after :load")
check.eq(#repl.complete("nosuchname", ""), 0, "nothing to complete")

check.done()
