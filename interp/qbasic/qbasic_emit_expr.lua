-- QBasic front end, pass 5 (expressions): the Lua code of a typed expression.
--   value(e, min, exact) -> code, precedence (parenthesised for precedence min; exact: SINGLE
--                           literals written as their SINGLE value)
--   cond(e)              -> a Lua condition for QBasic's "nonzero is true"
--   convert(e, ty)       -> the code of e stored in a variable of type ty (SINGLE rounding,
--                           CINT, ...), without a conversion that cannot change the value
--   lvalue(t), index(e), call_args(proc, args), literals: exact_text, lua_string
-- install(prog) binds them to the program's Lua names (prog.lua_name of the scope pass).
local K = require "qbasic_keywords"
local walk = require "qbasic_walk"

local M = {}

local f32 = require("pointcalc").qb.f32     -- SINGLE rounding (interp/qbasic/qbnum.c)

-- the shortest decimal text that reads back as exactly v
local function exact_text(v)
  if v == math.floor(v) and math.abs(v) < 2 ^ 53 then return string.format("%d", v) end
  for p = 9, 17 do
    local s = string.format("%." .. p .. "g", v)
    if tonumber(s) == v then return s end
  end
  return string.format("%.17g", v)
end

local function literal_text(e, exact)
  if e.ty == "int" or e.ty == "long" then return string.format("%d", e.v) end
  if e.ty == "single" then
    local s = f32(e.v)
    if exact and s ~= e.v then return exact_text(s) end
  end
  local t = e.text
  if t:find("&", 1, true) then return exact_text(e.v) end
  t = t:gsub("[!#%%&]$", ""):gsub("[dD]", "e"):gsub("E", "e")
  if t:match("e[+-]?$") then t = t .. "0" end
  if tonumber(t) ~= e.v then return exact_text(e.v) end
  return t
end

local function lua_string(s)
  local q = string.format("%q", s)
  return (q:gsub("\\\n", "\\n"):gsub("\r", "\\r"))
end

M.exact_text, M.literal_text, M.lua_string, M.f32 = exact_text, literal_text, lua_string, f32

local prog, lua_name     -- the program being emitted (install)
local emit_value, emit_cond, convert
function M.install(p)
  prog, lua_name = p, p.lua_name
end

-- ---- expressions --------------------------------------------------------------------------
-- Lua precedences: or 1, and 2, comparison 3, .. 9, + - 10, * / 11, unary 12, ^ 14, atom 20

local function wrap(code, prec, min)
  if prec < min then return "(" .. code .. ")" end
  return code
end

local function is_lit(e) return e.k == "num" or (e.k == "paren" and is_lit(e.a)) end
local function lit_value(e) if e.k == "paren" then return lit_value(e.a) end return e.v end
local function strip(e) while e.k == "paren" do e = e.a end return e end
M.strip = strip

-- does evaluating e have effects or possible errors (for AND/OR: QBasic evaluates both sides)
local function effectful(e)
  local found = false
  walk.expr(e, function(n)
    local k = n.k
    if k == "ucall" or k == "fncall" or k == "index" then found = true
    elseif k == "call" and (n.fn == "rnd" or n.fn == "sqr" or n.fn == "log" or n.fn == "point"
        or n.fn == "timer" or n.fn:match("%$$") or n.fn == "asc" or n.fn == "instr"
        or n.fn == "cint" or n.fn == "clng" or n.fn == "exp") then found = true
    elseif k == "bin" and (n.op == "/" or n.op == "\\" or n.op == "mod" or n.op == "^") then
      found = true
    end
  end)
  return found
end

local function fn_lua(fn) return K.FUNCS[fn] and K.FUNCS[fn].lua or fn end


local function args_code(args, exact)
  local t = {}
  for i, a in ipairs(args) do t[i] = (emit_value(a, 0, exact)) end
  return table.concat(t, ", ")
end

-- the arguments of a SUB or FUNCTION call (the resolve pass checked them): arrays by name,
-- values converted to the parameter's type
function M.call_args(proc, args)
  local t = {}
  for i, a in ipairs(args) do
    local p = proc.params[i]
    if p.array then t[i] = lua_name(a)
    elseif K.is_record(p.ty) then t[i] = (emit_value(a, 0))   -- by reference: the table
    else t[i] = convert(a, p.ty) end
  end
  return table.concat(t, ", ")
end
local call_args = M.call_args

-- a field of a record: base.x (["x"] for a name Lua reserves)
function M.field(e)
  local code = e.base.k == "index" and M.index(e.base) or lua_name(e.base)
  for _, f in ipairs(e.path) do
    if K.LUA_KEYWORDS[f] or not f:match("^[%a_][%w_]*$") then
      code = code .. "[" .. lua_string(f) .. "]"
    else
      code = code .. "." .. f
    end
  end
  return code
end

function M.index(e)
  local parts = { lua_name(e) }
  for _, a in ipairs(e.args) do parts[#parts + 1] = "[" .. emit_value(a, 0) .. "]" end
  return table.concat(parts)
end

-- emit_value(e, min, exact) -> code (parenthesised for precedence min)
function M.value(e, min, exact)
  min = min or 0
  local k = e.k
  if k == "num" then
    return literal_text(e, exact), 20
  elseif k == "str" then
    return lua_string(e.v), 20
  elseif k == "paren" then
    return emit_value(e.a, min, exact)
  elseif k == "var" then
    return lua_name(e), 20
  elseif k == "index" then
    return M.index(e), 20
  elseif k == "field" then
    return M.field(e), 20
  elseif k == "neg" then
    local ex = exact or e.ty == "double"
    local a = emit_value(e.a, 12, ex)
    if a:sub(1, 1) == "-" then a = "(" .. a .. ")" end
    return wrap("-" .. a, 12, min), 12
  elseif k == "bin" then
    local op = e.op
    local ex = exact or e.ty == "double"
    if e.ty == "string" then
      -- (checked: a QBasic string has at most 32,767 characters)
      return "cat(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    end
    if op == "+" or op == "-" then
      local code = emit_value(e.a, 10, ex) .. " " .. op .. " " .. emit_value(e.b, 11, ex)
      return wrap(code, 10, min), 10
    elseif op == "*" and (e.ty == "int" or e.ty == "long") then
      -- INTEGER and LONG products are checked as in QBasic (Overflow): unchecked, Lua's
      -- 64-bit integers would wrap around (65536& ^ 4 gives 0)
      local f = e.ty == "int" and "imul" or "lmul"
      return f .. "(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    elseif op == "*" then
      local code = emit_value(e.a, 11, ex) .. " * " .. emit_value(e.b, 12, ex)
      return wrap(code, 11, min), 11
    elseif op == "/" then
      if is_lit(e.b) and lit_value(e.b) ~= 0 then
        local code = emit_value(e.a, 11, ex) .. " / " .. emit_value(e.b, 12, ex)
        return wrap(code, 11, min), 11
      end
      return "div(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    elseif op == "^" then
      local b = strip(e.b)
      if b.k == "num" and b.v >= 0 and b.v == math.floor(b.v) then
        local code = emit_value(e.a, 15, ex) .. " ^ " .. emit_value(e.b, 14, ex)
        return wrap(code, 14, min), 14
      end
      return "pow(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    elseif op == "\\" then
      return "idiv(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    elseif op == "mod" then
      return "mod(" .. emit_value(e.a, 0, ex) .. ", " .. emit_value(e.b, 0, ex) .. ")", 20
    end
    error("unknown operator " .. op)
  elseif k == "rel" then
    return "truth(" .. emit_cond(e, 0) .. ")", 20
  elseif k == "logic" then
    local f = ({ ["and"] = "band", ["or"] = "bor", xor = "bxor", eqv = "beqv", imp = "bimp" })[e.op]
    return f .. "(" .. emit_value(e.a, 0) .. ", " .. emit_value(e.b, 0) .. ")", 20
  elseif k == "not" then
    return "bnot(" .. emit_value(e.a, 0) .. ")", 20
  elseif k == "call" then
    if e.bytes then return tostring(e.bytes), 20 end    -- LEN of a record: its size
    local fn = e.fn
    if fn == "lbound" or fn == "ubound" then
      local arr = e.args[1]
      local code = fn .. "(" .. lua_name(arr)
      if e.args[2] then code = code .. ", " .. emit_value(e.args[2], 0) end
      return code .. ")", 20
    end
    if fn == "str$" and (e.args[1].ty == "double" or e.args[1].ty == "long") then
      return "str(" .. emit_value(e.args[1], 0, true) .. ", \"" .. e.args[1].ty .. "\")", 20
    end
    local ex = exact or e.ty == "double"
    return fn_lua(fn) .. "(" .. args_code(e.args, ex) .. ")", 20
  elseif k == "ucall" then
    local proc = prog.proc_by_name[e.name]
    local code = proc.lua .. "(" .. call_args(proc, e.args) .. ")"
    local byref = false
    for i, p in ipairs(proc.params) do if proc.modified[i] and not p.array then byref = true end end
    if not byref then return code, 20 end
    -- a FUNCTION that assigns to its parameters returns them after its result (as a SUB
    -- does): by reference, they are copied back to the arguments that are variables
    local targets, any = {}, false
    for i, p in ipairs(proc.params) do
      if proc.modified[i] and not p.array then
        local a = e.args[i]
        if (a.k == "var" and not a.const) or a.k == "index" then
          targets[#targets + 1] = M.lvalue(a)
          any = true
        else
          targets[#targets + 1] = "_"
        end
      end
    end
    if not any then return "(" .. code .. ")", 20 end
    return "(function() local _r, _ _r, " .. table.concat(targets, ", ") .. " = " .. code
      .. " return _r end)()", 20
  elseif k == "fncall" then
    local proc = prog.fn_by_name[e.name]
    local t = {}
    for i, a in ipairs(e.args) do t[i] = convert(a, proc.params[i].ty) end
    return proc.lua .. "(" .. table.concat(t, ", ") .. ")", 20
  elseif k == "result" then
    return e.proc.result, 20
  end
  error("cannot emit expression " .. tostring(k))
end

local function boolish(e)
  e = strip(e)
  if e.k == "rel" then return true end
  if e.k == "not" then return boolish(e.a) end
  if e.k == "logic" and (e.op == "and" or e.op == "or" or e.op == "xor" or e.op == "eqv") then
    return boolish(e.a) and boolish(e.b)
  end
  return false
end

local RELOP_LUA = { ["="] = "==", ["<>"] = "~=", ["<"] = "<", [">"] = ">", ["<="] = "<=",
  [">="] = ">=" }
M.RELOP_LUA = RELOP_LUA
-- operands of comparisons: single literals stand for their SINGLE value
local function rel_operand(e)
  return (emit_value(e, 4, true))
end

-- a Lua condition (boolean) for QBasic's "nonzero is true"
function M.cond(e, min)
  min = min or 0
  local s = strip(e)
  if s.k == "rel" then
    local code = rel_operand(s.a) .. " " .. RELOP_LUA[s.op] .. " " .. rel_operand(s.b)
    return wrap(code, 3, min), 3
  elseif s.k == "not" and boolish(s.a) then
    return wrap("not " .. emit_cond(s.a, 12), 12, min), 12
  elseif s.k == "logic" and boolish(s) then
    if s.op == "and" or s.op == "or" then
      if effectful(s.b) then
        local f = s.op == "and" and "both" or "either"
        return f .. "(" .. emit_cond(s.a, 0) .. ", " .. emit_cond(s.b, 0) .. ")", 20
      end
      local p = s.op == "and" and 2 or 1
      local code = emit_cond(s.a, p) .. " " .. s.op .. " " .. emit_cond(s.b, p + 1)
      return wrap(code, p, min), p
    elseif s.op == "xor" then
      return wrap(emit_cond(s.a, 4) .. " ~= " .. emit_cond(s.b, 4), 3, min), 3
    elseif s.op == "eqv" then
      return wrap(emit_cond(s.a, 4) .. " == " .. emit_cond(s.b, 4), 3, min), 3
    end
  end
  return wrap(emit_value(e, 4) .. " ~= 0", 3, min), 3
end

-- is e's value exactly a SINGLE already (no rounding needed to store it)?
local function exact_single(e)
  e = strip(e)
  local k = e.k
  if k == "num" then return f32(e.v) == e.v end
  if k == "var" or k == "index" or k == "result" or k == "field" then
    return e.ty == "single" or e.ty == "int"
  end
  if k == "neg" then return exact_single(e.a) end
  if k == "call" then
    if e.fn == "rnd" or e.fn == "csng" or e.fn == "cint" or e.fn == "sgn" or e.fn == "point"
        or e.fn == "len" or e.fn == "asc" or e.fn == "lbound" or e.fn == "ubound" then
      return true
    end
    if e.fn == "int" or e.fn == "fix" or e.fn == "abs" then return exact_single(e.args[1]) end
  end
  if k == "ucall" or k == "fncall" then return e.ty == "single" or e.ty == "int" end
  return false
end
local function exact_int(e)
  e = strip(e)
  if e.k == "num" then return e.ty == "int" end
  if e.k == "var" or e.k == "index" or e.k == "result" or e.k == "ucall" or e.k == "fncall"
      or e.k == "field" then
    return e.ty == "int"
  end
  if e.k == "call" then
    return e.fn == "cint" or e.fn == "sgn" or e.fn == "point" or e.fn == "asc" or e.fn == "lbound"
      or e.fn == "ubound"
  end
  if e.k == "rel" then return true end
  return false
end

-- an INTEGER/LONG literal stored in a SINGLE or DOUBLE variable is written as a Lua float
-- (320.0), so that the variable never holds a Lua integer (whose products would wrap around)
local function float_literal(e)
  local s = strip(e)
  local neg = false
  if s.k == "neg" then neg = true; s = strip(s.a) end
  if s.k == "num" and (s.ty == "int" or s.ty == "long") then
    return (neg and "-" or "") .. string.format("%d", s.v) .. ".0"
  end
end

function M.convert(e, ty)
  if ty == "string" then return (emit_value(e, 0)) end
  if ty == "double" or (ty == "single" and exact_single(e)) then
    local f = float_literal(e)
    if f then return f end
  end
  if ty == "double" then
    if e.ty == "single" and not exact_single(e) then
      return "csng(" .. emit_value(e, 0) .. ")"
    end
    return (emit_value(e, 0, true))
  end
  if ty == "single" then
    if exact_single(e) then return (emit_value(e, 0)) end
    return "csng(" .. emit_value(e, 0) .. ")"
  end
  if ty == "int" then
    if exact_int(e) then return (emit_value(e, 0)) end
    return "cint(" .. emit_value(e, 0) .. ")"
  end
  if ty == "long" then
    local s = strip(e)
    if exact_int(e) or (s.k == "num" and s.ty == "long")
        or ((s.k == "var" or s.k == "index" or s.k == "field") and s.ty == "long") then
      return (emit_value(e, 0))
    end
    return "clng(" .. emit_value(e, 0) .. ")"
  end
  error("bad type " .. tostring(ty))
end

function M.lvalue(t)
  if t.k == "field" then return M.field(t) end
  if t.k == "var" then return lua_name(t)
  elseif t.k == "index" then return M.index(t)
  elseif t.k == "result" then return t.proc.result end
  error("bad lvalue")
end

emit_value, emit_cond, convert = M.value, M.cond, M.convert

-- the code of e stored into target: converted to its type, a fixed-length string padded or
-- cut to its length, a record copied (QBasic assigns records by value)
function M.store(e, target)
  if target.fixed then return "fixstr(" .. emit_value(e, 0) .. ", " .. target.fixed .. ")" end
  if K.is_record(target.ty) then return "rec_copy(" .. emit_value(e, 0) .. ")" end
  return convert(e, target.ty)
end

return M
