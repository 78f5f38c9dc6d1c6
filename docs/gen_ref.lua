-- The man page pointcalc-api(7) and the Lua language-server definitions (`---@meta`), both from
-- the help registry (interp/help.lua), through one model of it built here:
--   pointcalc docs/gen_ref.lua man VERSION > pointcalc-api.7
--   pointcalc docs/gen_ref.lua meta DIR      writes DIR/pointcalc.lua (the module), DIR/globals.lua
--                                            (the program's globals) and DIR/types.lua (classes)
-- The registry's signature strings ("lerp(A, B, t) -> value", "conic.circle{A =, B =} -> curve")
-- are parsed once into entries with parameters, optional parts, option keys and result types;
-- `model()` is the one place that reads the registry, so a declared argument layer can replace
-- its source without touching the writers.
local help = require "help"

-- --- the model -------------------------------------------------------------------------------
-- Types guessed from the books' naming habits: capitals are points (or vectors), t/k/x... numbers.
local CLASS = {p = "pc.point", S = "pc.simplex", f = "pc.map", c = "pc.curve", M = "pc.equation",
               s = "pc.surface", C = "pc.curvilinear", z = "pc.complex"}
local RESULT = {point = "pc.point", vector = "pc.point", value = "pc.point|number", number = "number",
                integer = "integer", boolean = "boolean", string = "string", curve = "pc.curve",
                c = "pc.curve", s = "pc.surface", surface = "pc.surface", f = "pc.map", map = "pc.map",
                g = "function", S = "pc.simplex", simplex = "pc.simplex", equation = "pc.equation",
                C = "pc.curvilinear", z = "pc.complex", complex = "pc.complex", left = "pc.curve",
                right = "pc.curve", rows = "number[][]", quads = "table", samples = "table",
                iterator = "function", energy = "number", residual = "number", lambda = "number",
                mu = "number", k = "number", mse = "number", ratio = "number", lo = "pc.point",
                hi = "pc.point", K = "pc.point"}
local NUMBER = {t = 1, k = 1, x = 1, y = 1, z = 1, r = 1, n = 1, m = 1, i = 1, j = 1, a = 1, b = 1,
                u = 1, v = 1, w = 1, eps = 1, lambda = 1, mu = 1, tol = 1, step = 1, min = 1,
                max = 1, default = 1, c = 1, e = 1, h = 1, d = 1, p = 1, q = 1, fz = 1}

local VECTOR_AREA = {points = true, values = true}   -- u, v, w are vectors: dot(u, v), p:cross(v)
local DRAW_AREA = {draw = true, qbscreen = true}   -- there c is a colour: pset(x, y [, c])
local area_id

local function ptype(name)
  if name == "..." then return "any" end
  if VECTOR_AREA[area_id] and (name == "u" or name == "v" or name == "w") then return "pc.vector" end
  if DRAW_AREA[area_id] and (name == "c" or name == "fg") then return "integer|string" end   -- a colour
  if NUMBER[name] or name:match("^[a-z]%d$") or name:match("^t%d") or name:match("^th%d")
     or name:match("^ph%d") or name:match("^[uv]%d") or name:match("^[xy]%d") then
    return "number"
  end
  if name:match("^%u%w*$") then return "pc.point" end
  if name == "points" or name == "tangents" or name == "nodes" then return "pc.point[]" end
  if name == "curve" then return "pc.curve" end
  if name == "text" or name == "path" or name == "name" or name == "mode" or name == "code" then
    return "string"
  end
  if name == "fn" or name == "g" then return "function" end
  if name == "colour" or name == "color" or name == "border" or name == "bg" then return "integer|string" end
  if name == "direction" or name == "style" or name == "kind" or name == "family" then return "string" end
  if name == "scale" or name == "aspect" or name == "start" or name == "end_" or name == "re"
     or name == "im" or name == "degree" or name == "order" then return "number" end
  if name == "map" or name == "f" then return "pc.map" end
  if name == "opts" or name == "options" then return "table" end
  return "any"
end

local KEYWORDS = {["and"] = 1, ["end"] = 1, ["in"] = 1, ["or"] = 1, ["not"] = 1, ["do"] = 1,
                  ["if"] = 1, ["for"] = 1, ["then"] = 1, ["nil"] = 1, ["function"] = 1}

-- Split s at `sep` (one character) outside brackets and quotes.
local function split_top(s, sep)
  local parts, depth, start, quote = {}, 0, 1, nil
  for i = 1, #s do
    local ch = s:sub(i, i)
    if quote then
      if ch == quote then quote = nil end
    elseif ch == '"' then quote = ch
    elseif ch:match("[%(%[{]") then depth = depth + 1
    elseif ch:match("[%)%]}]") then depth = depth - 1
    elseif ch == sep and depth == 0 then
      parts[#parts + 1] = s:sub(start, i - 1); start = i + 1
    end
  end
  parts[#parts + 1] = s:sub(start)
  return parts
end

local function trim(s) return (s:match("^%s*(.-)%s*$")) end

-- Keys of an option table "{A =, B = [, delta = | R =], color = c}".
local function parse_keys(s)
  local keys, optional = {}, false
  for part in s:gmatch("[^,|]+") do
    if part:find("%[") then optional = true end
    local k = part:match("([%a_][%w_]*)%s*=")
    if k then
      local v = part:match("=%s*(.-)%s*[%]]*%s*$") or ""
      local ty = (v:match("^[%d.-]+$") and "number") or (v:match("^true") or v:match("^false")) and
                 "boolean" or (v:match('^"') and "string") or (v:match("^{") and "table") or ptype(k)
      -- a key shown with a value ("closed = false") has that default, so it may be left out
      keys[#keys + 1] = {name = k, type = ty, optional = optional or v ~= ""}
    end
  end
  return keys
end

-- Positional parameters of "A, B [, C [, D]]": name, type, optional.
local function parse_params(s)
  local params, optional, token, depth = {}, false, {}, 0
  local function flush()
    local t = trim(table.concat(token)); token = {}
    if t == "" then return end
    local p
    if t:match("^%.%.%.") or t:match("^[%w_]*, %.%.%.") then p = {name = "...", type = "any"}
    elseif t:match('^"') then p = {name = "mode", type = "string"}
    elseif t:match("^{.*=") then p = {name = "opts", type = "table", keys = parse_keys(t:match("^{(.*)}") or "")}
    elseif t:match("^{") then p = {name = "list", type = "table"}
    elseif t:find("|", 1, true) then p = {name = t:match("^([%a_][%w_]*)") or "arg", type = "any"}
    else
      local n = t:match("^([%a_][%w_]*)")
      p = {name = n or "arg", type = n and ptype(n) or "any"}
      if t:match("=") then p.type = "any" end   -- "n = 1001": a default
    end
    p.optional = optional
    params[#params + 1] = p
  end
  local i = 1
  while i <= #s do
    local ch = s:sub(i, i)
    if ch == "[" and depth == 0 then flush(); optional = true
    elseif ch == "]" and depth == 0 then flush()
    elseif ch == "," and depth == 0 then flush()
    elseif ch == '"' then
      local j = s:find('"', i + 1, true) or #s
      token[#token + 1] = s:sub(i, j); i = j
    else
      if ch:match("[%({]") then depth = depth + 1 elseif ch:match("[%)}]") then depth = depth - 1 end
      token[#token + 1] = ch
    end
    i = i + 1
  end
  flush()
  -- unique Lua names, varargs last
  local seen, out, vararg = {}, {}, false
  for _, p in ipairs(params) do
    if p.name == "..." then vararg = true
    else
      local n = p.name
      if KEYWORDS[n] then n = n .. "_" end
      while seen[n] do n = n .. "_" end
      seen[n] = true; p.name = n
      out[#out + 1] = p
    end
  end
  if vararg then out[#out + 1] = {name = "...", type = "any", optional = true} end
  return out
end

local function parse_results(s)
  local out = {}
  if not s then return out end
  for r in s:gmatch("[^,]+") do
    r = trim(r)
    local word = r:match("^([%a_][%w_]*)")
    if r:match("^{") then out[#out + 1] = "table"
    elseif word then out[#out + 1] = RESULT[word] or "any" end
  end
  return out
end

-- One callable form "head(params) -> results" or "head{keys} -> results", or nil.
local function parse_form(f)
  local lhs, rhs = f:match("^(.-)%s*%->%s*(.*)$")
  lhs = trim(lhs or f)
  local head, open = lhs:match("^([%a_][%w_.:]*)%s*([%({])")
  if not head then return nil end
  local inner = lhs:match("^[%a_][%w_.:]*%s*%b()$") and lhs:match("%((.*)%)$")
             or lhs:match("^[%a_][%w_.:]*%s*%b{}$") and lhs:match("{(.*)}$")
  if not inner then return nil end
  local form = {head = head, results = parse_results(rhs), text = f}
  if open == "{" then
    form.params = {{name = "opts", type = "table", keys = parse_keys(inner)}}
  else
    form.params = parse_params(inner)
  end
  return form
end

-- A form whose arguments hold alternatives outside brackets, "label(text, P | x, y [, dir])",
-- as the forms it stands for: "label(text, P [, dir])" and "label(text, x, y [, dir])".
local function expand(piece)
  local head, inner, tail = piece:match("^([%a_][%w_.:]*%s*%()(.*)(%).-)$")
  if not inner then return {piece} end
  local depth, bar = 0, nil
  for i = 1, #inner do
    local ch = inner:sub(i, i)
    if ch:match("[%(%[{]") then depth = depth + 1
    elseif ch:match("[%)%]}]") then depth = depth - 1
    elseif ch == "|" and depth == 0 then bar = i; break end
  end
  if not bar then return {piece} end
  local left, right = trim(inner:sub(1, bar - 1)), trim(inner:sub(bar + 1))
  local at = right:find("[", 1, true)
  local opt = at and right:sub(at) or ""
  local prefix = left:match("^(.*,)%s*[^,]*$") or ""
  return {head .. left .. (opt ~= "" and " " .. opt or "") .. tail,
          head .. (prefix ~= "" and prefix .. " " or "") .. right .. tail}
end

-- Every entry with its forms parsed; sub-forms joined by " | " or by two spaces are separate.
local function model()
  local m = {areas = {}, entries = {}}
  for _, a in ipairs(help.areas) do
    local area = {id = a.id, title = a.title, intro = a.intro, entries = {}}
    m.areas[#m.areas + 1] = area
    area_id = a.id
    for _, e in ipairs(a.entries) do
      local entry = {name = e.name, kind = e.kind, desc = e.desc, sigs = help.forms(e), forms = {}}
      for _, sig in ipairs(entry.sigs) do
        for _, alt in ipairs(split_top(sig, "|")) do
          for piece in (alt .. "  "):gmatch("(.-)%s%s+") do
            for _, one in ipairs(expand(trim(piece))) do
              local f = parse_form(one)
              if f then entry.forms[#entry.forms + 1] = f end
            end
          end
        end
      end
      -- "f(a) | f(b) -> r": the results written once belong to every form
      local shared
      for _, f in ipairs(entry.forms) do if #f.results > 0 then shared = f.results end end
      for _, f in ipairs(entry.forms) do if #f.results == 0 and shared then f.results = shared end end
      area.entries[#area.entries + 1] = entry
      m.entries[#m.entries + 1] = entry
    end
  end
  return m
end

-- --- pointcalc-api(7) -------------------------------------------------------------------------
local function roff(s)
  s = s:gsub("\\", "\\e"):gsub("%-", "\\-")
  s = s:gsub("`([^`]+)`", "\\fB%1\\fR")
  if s:match("^[.']") then s = "\\&" .. s end
  return s
end

local function write_man(m, version)
  local out = {}
  local function put(...) for _, s in ipairs({...}) do out[#out + 1] = s end end
  put('.TH POINTCALC-API 7 "" "pointcalc ', version or "", '" "pointcalc"\n')
  -- left-aligned: signatures are long words that justified lines could not adjust around
  put(".ad l\n")
  put(".SH NAME\npointcalc-api \\- every function of pointcalc with its signature\n")
  put(".SH DESCRIPTION\n",
      "The names below are globals in a script run by\n.BR pointcalc (1)\n",
      "and fields of the module in the stock interpreter\n",
      "(\\fBlocal pc = require \"pointcalc\"\\fR).\n",
      "In the REPL, \\fB:help\\fR \\fINAME\\fR prints the same signature and description.\n",
      "Square brackets mark optional arguments, \\fB{\\fR\\fIkey\\fR \\fB=}\\fR an option table,\n",
      "and \\fB\\->\\fR what a function returns.\n")
  for _, a in ipairs(m.areas) do
    put(".SH ", roff(a.title:upper()), "\n", roff(a.intro), "\n")
    for _, e in ipairs(a.entries) do
      put(".TP\n")
      for i, sig in ipairs(e.sigs) do
        if i > 1 then put(".br\n") end
        -- a break point after each "|": long lists of choices must not overrun the line
        put("\\fB", (roff(sig):gsub("|", "|\\:")), "\\fR\n")
      end
      put(roff(e.desc), "\n")
    end
  end
  put(".SH SEE ALSO\n.BR pointcalc (1),\n.BR lua5.4 (1)\n")
  return table.concat(out)
end

-- --- the language-server definitions ---------------------------------------------------------
local function luatype(p)
  if p.keys and #p.keys > 0 then
    local ks = {}
    for _, k in ipairs(p.keys) do ks[#ks + 1] = k.name .. (k.optional and "?" or "") .. ": " .. k.type end
    return "{" .. table.concat(ks, ", ") .. "}"
  end
  return p.type
end

local function comment(put, text)
  for line in (text .. "\n"):gmatch("(.-)\n") do put("--- ", line, "\n") end
end

-- ---@param / ---@return lines and the Lua parameter list of one form
local function signature(put, f)
  local names = {}
  for _, p in ipairs(f.params) do
    if p.name == "..." then put("---@param ... any\n")
    else put("---@param ", p.name, p.optional and "? " or " ", luatype(p), "\n") end
    names[#names + 1] = p.name
  end
  for _, r in ipairs(f.results) do put("---@return ", r, "\n") end
  return table.concat(names, ", ")
end

local function funtype(f)
  local ps, rs = {}, {}
  for _, p in ipairs(f.params) do
    ps[#ps + 1] = p.name == "..." and "...: any" or p.name .. (p.optional and "?" or "") .. ": " .. luatype(p)
  end
  for _, r in ipairs(f.results) do rs[#rs + 1] = r end
  return "fun(" .. table.concat(ps, ", ") .. ")" .. (#rs > 0 and ": " .. table.concat(rs, ", ") or "")
end

-- the functions of the API (not methods, fields, operators or REPL commands) under a prefix
local function write_api(m, prefix, header, footer)
  local out = {}
  local function put(...) for _, s in ipairs({...}) do out[#out + 1] = s end end
  put(header)
  -- namespaces first: "map.scale" needs the table map; a namespace that is also a function
  -- (surface, affine, oneratio, complex) is a table with a call overload
  local ns, fn = {}, {}
  for _, e in ipairs(m.entries) do
    if e.kind == "function" then
      fn[e.name] = e
      local p = e.name:match("^([%a_][%w_]*)%.")
      if p and not ns[p] then ns[p] = true; ns[#ns + 1] = p end
    end
  end
  for _, p in ipairs(ns) do
    local e = fn[p]
    put("\n---@class pc.", prefix == "" and "global." or "lib.", p, "\n")
    if e then
      comment(put, e.desc)
      for _, f in ipairs(e.forms) do put("---@overload ", funtype(f), "\n") end
    end
    put(prefix, p, " = {}\n")
  end
  for _, e in ipairs(m.entries) do
    if e.kind == "function" and not ns[e.name] then
      put("\n")
      comment(put, e.desc)
      local first = e.forms[1]
      for i = 2, #e.forms do put("---@overload ", funtype(e.forms[i]), "\n") end
      local params = first and signature(put, first) or "..."
      put("function ", prefix, e.name, "(", params, ") end\n")
    elseif e.kind == "value" then
      put("\n")
      comment(put, e.desc)
      put("---@type ", e.name == "_VERSION" and "string" or "pc.complex", "\n", prefix, e.name, " = nil\n")
    end
  end
  put(footer)
  return table.concat(out)
end

-- the classes: methods from the "p:lerp(...)" forms, fields, operators
local function write_types(m)
  local classes, order = {}, {}
  local function class(name)
    if not classes[name] then classes[name] = {fields = {}, ops = {}, methods = {}}; order[#order + 1] = name end
    return classes[name]
  end
  for _, n in ipairs({"pc.point", "pc.simplex", "pc.map", "pc.curve", "pc.surface", "pc.equation",
                      "pc.curvilinear", "pc.complex"}) do class(n) end
  local p, mp = class("pc.point"), class("pc.map")
  p.ops = {"add(pc.point): pc.point", "sub(pc.point): pc.point", "mul(number): pc.point",
           "div(number): pc.point", "unm: pc.point", "len: integer"}
  mp.ops = {"mul(pc.map): pc.map", "call(pc.point): pc.point"}
  class("pc.curve").ops = {"call(number): pc.point"}
  class("pc.surface").ops = {"call(number, number): pc.point"}
  class("pc.simplex").ops = {"call(number, number): pc.point"}
  class("pc.equation").ops = {"call(number): pc.point", "add(pc.equation): pc.equation",
                              "mul(number): pc.equation"}
  class("pc.curvilinear").ops = {"call(number, number): pc.point"}
  for _, e in ipairs(m.entries) do
    local recv = e.name:match("^(%a)[%.:%[]") or e.name:match("^(%a)%(")
    local cls = recv and CLASS[recv]
    if cls and e.kind == "field" then
      for _, sig in ipairs(e.sigs) do
        local names, res = sig:match("^(.-)%s*%->%s*(.*)$")
        for fld in (names or ""):gmatch("%a%.([%a_][%w_]*)") do
          class(cls).fields[#class(cls).fields + 1] = {fld, RESULT[res] or "any", e.desc}
        end
        if sig:match("%[i%]") then class(cls).index = RESULT[res] or "any" end
      end
    elseif cls and e.kind == "method" then
      for _, f in ipairs(e.forms) do
        local r, meth = f.head:match("^(%a):([%a_][%w_]*)$")
        if r and CLASS[r] then
          class(CLASS[r]).methods[#class(CLASS[r]).methods + 1] = {meth, f, e.desc}
        end
      end
    end
  end
  local out = {"---@meta\n-- The value types of pointcalc (generated from the help registry by docs/gen_ref.lua).\n",
               "\n---@alias pc.vector pc.point\n"}
  local function put(...) for _, s in ipairs({...}) do out[#out + 1] = s end end
  for _, name in ipairs(order) do
    local c = classes[name]
    put("\n---@class ", name, "\n")
    for _, f in ipairs(c.fields) do put("---@field ", f[1], " ", f[2], " ", f[3], "\n") end
    if c.index then put("---@field [integer] ", c.index, "\n") end
    for _, o in ipairs(c.ops) do put("---@operator ", o, "\n") end
    local var = name:gsub("^pc%.", "")
    put("local ", var, " = {}\n")
    local seen = {}
    for _, mth in ipairs(c.methods) do
      local meth, f, desc = mth[1], mth[2], mth[3]
      if not seen[meth] then
        seen[meth] = true
        put("\n")
        comment(put, desc)
        local params = signature(put, f)
        put("function ", var, ":", meth, "(", params, ") end\n")
      end
    end
  end
  return table.concat(out)
end

local function write_file(path, text)
  local f = assert(io.open(path, "w"))
  f:write(text)
  f:close()
end

local mode, where = ...
if not mode then mode, where = arg and arg[1], arg and arg[2] end
local m = model()
if mode == "man" then
  io.write(write_man(m, where))
elseif mode == "meta" and where then
  write_file(where .. "/pointcalc.lua", write_api(m, "pointcalc.",
    "---@meta pointcalc\n-- pointcalc as a Lua module: `local pc = require \"pointcalc\"` (generated by docs/gen_ref.lua).\n\n---@class pointcalc\nlocal pointcalc = {}\n",
    "\nreturn pointcalc\n"))
  write_file(where .. "/globals.lua", write_api(m, "",
    "---@meta\n-- The globals of a script run by the pointcalc program (generated by docs/gen_ref.lua).\n", ""))
  write_file(where .. "/types.lua", write_types(m))
else
  io.stderr:write("usage: pointcalc docs/gen_ref.lua man [VERSION] | meta DIR\n")
  os.exit(2)
end
