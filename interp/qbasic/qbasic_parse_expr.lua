-- QBasic front end, the parser's first half: the token cursor and expressions.
--
-- cursor(prog) gives the parser state P: the tokens of the line being parsed (P.toks, P.pos),
-- its number (P.lineno), the procedure being parsed (P.cur_proc) and the helpers below.
-- Expressions become syntax trees without types (the resolve pass gives them):
--   num {v, ty, text}  str {v}  paren {a}  neg {a}  not {a}
--   bin {op, a, b}  rel {op, a, b}  logic {op, a, b}          (op: + - * / \ ^ mod; = <> ...)
--   var {name, sfx, text}  index {name, sfx, text, args}  arrayref {name, sfx, text}  (a())
--   call {fn, args} (built-in)  ucall {name, sfx, args} (FUNCTION)  fncall (DEF FN)
--   result {name, proc} (a FUNCTION's name assigned inside it)
--   field {base, path} (a(i).x; the resolve pass makes p.x of a record variable one too)
-- Names carry proc (the procedure they appear in, nil in the module) and line.
local K = require "qbasic_keywords"

local M = {}

local RELOPS = { ["="] = true, ["<>"] = true, ["<"] = true, [">"] = true, ["<="] = true,
  [">="] = true }
M.RELOPS = RELOPS

-- the cursor's methods (P:peek(), P:expr(), ...), over the parser state P
local C = {}
C.__index = C
M.methods = C

function M.cursor(prog)
  return setmetatable({ prog = prog, toks = nil, pos = 1, lineno = 0, cur_proc = nil }, C)
end

function C.err(P, msg, line)
  error({ qb = true, msg = msg or "Syntax error", line = line or P.lineno }, 0)
end
-- statements pointcalc knows but does not implement: named in the error
function C.unsupported(P, what)
  P:err(what .. ": not supported by pointcalc")
end
function C.peek(P, o) return P.toks[P.pos + (o or 0)] end
function C.next(P) local t = P.toks[P.pos]; P.pos = P.pos + 1; return t end
function C.is_op(P, v, o) local t = P.toks[P.pos + (o or 0)]; return t.t == "op" and t.v == v end
function C.is_kw(P, v, o) local t = P.toks[P.pos + (o or 0)]; return t.t == "kw" and t.v == v end
function C.accept_op(P, v) if P:is_op(v) then P.pos = P.pos + 1; return true end end
function C.accept_kw(P, v) if P:is_kw(v) then P.pos = P.pos + 1; return true end end
function C.expect_op(P, v) if not P:accept_op(v) then P:err() end end
function C.expect_kw(P, v) if not P:accept_kw(v) then P:err() end end
function C.at_end(P)   -- the end of a statement
  local t = P.toks[P.pos]
  return t.t == "eol" or (t.t == "op" and t.v == ":") or (t.t == "kw" and t.v == "else")
end

function C.name_node(P, k, tok, extra)
  local n = { k = k, name = tok.v, sfx = tok.sfx, text = tok.text, proc = P.cur_proc,
    line = P.lineno }
  for key, v in pairs(extra or {}) do n[key] = v end
  return n
end

function C.args(P)   -- after "(": expressions up to ")"
  local args = {}
  if P:accept_op(")") then return args end
  repeat args[#args + 1] = P:expr() until not P:accept_op(",")
  P:expect_op(")")
  return args
end

local function builtin(P, t)
  local f = K.FUNCS[t.v]
  if not f then
    if K.UNSUPPORTED_FUNCS[t.v] then P:unsupported(t.v:upper() .. " function") end
    P:err()
  end
  P.pos = P.pos + 1
  if t.v == "lbound" or t.v == "ubound" then
    P:expect_op("(")
    local a = P:next()
    if a.t ~= "id" then P:err() end
    local args = { P:name_node("arrayref", a) }
    if P:accept_op(",") then args[2] = P:expr() end
    P:expect_op(")")
    return { k = "call", fn = t.v, args = args, line = P.lineno }
  end
  if t.v == "input$" and P:is_op("(") then   -- INPUT$(n [, [#]file])
    P.pos = P.pos + 1
    local args = { P:expr() }
    if P:accept_op(",") then
      P:accept_op("#")
      args[2] = P:expr()
    end
    P:expect_op(")")
    return { k = "call", fn = t.v, args = args, line = P.lineno }
  end
  local args = {}
  if P:accept_op("(") then args = P:args() end
  return { k = "call", fn = t.v, args = args, line = P.lineno }
end

local function atom(P)
  local t = P:peek()
  if t.t == "num" then
    P.pos = P.pos + 1
    if t.overflow then P:err("Overflow") end
    return { k = "num", v = t.v, ty = t.ty, text = t.text }
  elseif t.t == "str" then
    P.pos = P.pos + 1
    return { k = "str", v = t.v, ty = "string" }
  elseif t.t == "op" and t.v == "(" then
    P.pos = P.pos + 1
    local e = P:expr()
    P:expect_op(")")
    return { k = "paren", a = e }
  elseif t.t == "id" then
    P.pos = P.pos + 1
    if t.v:sub(1, 2) == "fn" then            -- DEF FN call
      local args = {}
      if P:accept_op("(") then args = P:args() end
      return P:name_node("fncall", t, { args = args })
    end
    if P.prog.functions[t.v] then
      -- inside FUNCTION f, a bare f is a recursive call; QBasic treats "f" as the result
      -- variable on the left of "=" only
      local args = {}
      if P:accept_op("(") then args = P:args() end
      return P:name_node("ucall", t, { args = args })
    end
    if P:is_op("(") then
      if P:is_op(")", 1) then        -- a() : a whole array, as an argument
        P.pos = P.pos + 2
        return P:name_node("arrayref", t)
      end
      P.pos = P.pos + 1
      return P:fields(P:name_node("index", t, { args = P:args() }))
    end
    return P:name_node("var", t)
  elseif t.t == "kw" then
    return builtin(P, t)
  end
  P:err()
end

-- unary - and + in front of what `operand` parses; QBasic also allows them right after ^
-- (2 ^ -1), where they apply to the exponent only
local function signed(operand)
  local function parse(P)
    if P:accept_op("-") then return { k = "neg", a = parse(P) } end
    if P:accept_op("+") then return parse(P) end
    return operand(P)
  end
  return parse
end
local pow_operand = signed(atom)
local function power(P)
  local a = atom(P)
  while P:is_op("^") do
    P.pos = P.pos + 1
    a = { k = "bin", op = "^", a = a, b = pow_operand(P) }
  end
  return a
end
local function binary_level(sub, ops, kind)
  return function(P)
    local a = sub(P)
    while true do
      local t = P:peek()
      local op
      if (t.t == "op" or t.t == "kw") and ops[t.v] then op = t.v end
      if not op then return a end
      P.pos = P.pos + 1
      a = { k = kind or "bin", op = op, a = a, b = sub(P) }
    end
  end
end
local unary = signed(power)
local mul = binary_level(unary, { ["*"] = true, ["/"] = true })
local idiv = binary_level(mul, { ["\\"] = true })
local mod = binary_level(idiv, { mod = true })
local add = binary_level(mod, { ["+"] = true, ["-"] = true })
C.additive = add     -- CASE IS < x takes an operand of a relation
local function rel(P)
  local a = add(P)
  while P:peek().t == "op" and RELOPS[P:peek().v] do
    local op = P:next().v
    a = { k = "rel", op = op, a = a, b = add(P) }
  end
  return a
end
local function negation(P)
  if P:accept_kw("not") then return { k = "not", a = negation(P) } end
  return rel(P)
end
local function logic_level(sub, word)
  return binary_level(sub, { [word] = true }, "logic")
end
local land = logic_level(negation, "and")
local lor = logic_level(land, "or")
local lxor = logic_level(lor, "xor")
local leqv = logic_level(lxor, "eqv")
C.expr = logic_level(leqv, "imp")

-- an assignable reference: variable or array element (or a FUNCTION's result inside it)
function C.lvalue(P)
  local t = P:next()
  if t.t ~= "id" then P:err() end
  local cur = P.cur_proc
  if t.v:sub(1, 2) == "fn" and cur and cur.kind == "deffn" and cur.name == t.v then
    return { k = "result", name = t.v, proc = cur }
  end
  if P.prog.functions[t.v] then
    if cur and cur.kind == "function" and cur.name == t.v then
      return { k = "result", name = t.v, proc = cur }
    end
    P:err("Duplicate definition")
  end
  if P:is_op("(") then
    P.pos = P.pos + 1
    local args = P:args()
    if #args == 0 then P:err() end
    return P:fields(P:name_node("index", t, { args = args, lvalue = true }))
  end
  return P:name_node("var", t, { lvalue = true })
end

-- a(i).x.y: fields of a record element (a.x of a scalar lexes as one name: the resolve pass
-- splits it)
function C.fields(P, base)
  local t = P:peek()
  if t.t ~= "field" then return base end
  P.pos = P.pos + 1
  local path = {}
  for f in t.v:gmatch("[^%.]+") do path[#path + 1] = f end
  return { k = "field", base = base, path = path, lvalue = base.lvalue, line = P.lineno }
end

-- (x, y) or STEP (x, y)
function C.coord_pair(P)
  local step = P:accept_kw("step")
  P:expect_op("(")
  local x = P:expr()
  P:expect_op(",")
  local y = P:expr()
  P:expect_op(")")
  return { step = step, x = x, y = y }
end

function C.opt_expr(P)   -- an optional argument: nil when left out
  if P:is_op(",") or P:at_end() then return nil end
  return P:expr()
end

-- a label: a line number 0..65529 or a name
function C.label_name(P, t)
  if t.t == "num" and t.v == math.floor(t.v) and t.v >= 0 and t.v <= 65529 then
    return string.format("%d", t.v)
  elseif t.t == "id" and not t.sfx then
    return t.v
  end
  P:err()
end

return M
