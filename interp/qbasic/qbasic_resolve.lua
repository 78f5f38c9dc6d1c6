-- QBasic front end, pass 2: resolve and check.  Walks the syntax tree in the program's textual
-- order (DEFINT, DIM ... AS, SHARED and CONST apply to what follows them, as in QBasic), gives
-- every expression and variable its type (e.ty: int long single double string), marks CONST
-- references (e.const) and checks what QBasic checks before a program runs: Type mismatch,
-- Argument-count mismatch, Parameter type mismatch, Duplicate definition, Subprogram / Function
-- not defined, FOR variables, SELECT CASE values.  Each statement kind has a short function in
-- CHECK below.  Names, labels and GOTOs are the next passes' (qbasic_scope, qbasic_control).
local K = require "qbasic_keywords"

local M = {}

local TYPE_OF_SUFFIX, NUM_RANK = K.TYPE_OF_SUFFIX, K.NUM_RANK

local function qerr(msg, line) error({ qb = true, msg = msg or "Syntax error", line = line }, 0) end

local function err(R, msg) qerr(msg, R.line) end

-- ---- types of names ---------------------------------------------------------------------
local function type_of_name(R, n, is_array)
  if n.sfx then return TYPE_OF_SUFFIX[n.sfx] end
  local as = is_array and R.scope.as_array or R.scope.as_scalar
  if as[n.name] then
    -- a fixed-length string (DIM s AS STRING * 8): stores pad or cut it to its length
    n.fixed = (is_array and R.scope.fixed_array or R.scope.fixed)[n.name]
    return as[n.name]
  end
  if R.scope ~= R.main_scope then
    local sas = is_array and R.prog.shared_arrays or R.prog.shared
    if sas[n.name] and sas[n.name].as then
      n.fixed = sas[n.name].fixed
      return sas[n.name].as
    end
  end
  return R.deftype[n.name:sub(1, 1)]
end
local function fn_result_type(R, n)
  if n.sfx then return TYPE_OF_SUFFIX[n.sfx] end
  return R.deftype[n.name:sub(1, 1)]
end

-- ---- expressions ------------------------------------------------------------------------
local expr
local function num(R, e) if not NUM_RANK[expr(R, e)] then err(R, "Type mismatch") end return e end
local function str(R, e) if expr(R, e) ~= "string" then err(R, "Type mismatch") end return e end
local function opt_num(R, e) if e then num(R, e) end end

local function arith_type(R, a, b, op)
  if K.is_record(a.ty) or K.is_record(b.ty) then err(R, "Type mismatch") end
  if a.ty == "string" or b.ty == "string" then
    if op == "+" and a.ty == "string" and b.ty == "string" then return "string" end
    err(R, "Type mismatch")
  end
  local r = NUM_RANK[a.ty] >= NUM_RANK[b.ty] and a.ty or b.ty
  if op == "/" and (r == "int" or r == "long") then r = "single" end
  if op == "^" then r = (r == "double") and "double" or "single" end
  if op == "\\" or op == "mod" then r = (a.ty == "int" and b.ty == "int") and "int" or "long" end
  return r
end
local function logic_type(R, a, b)
  num(R, a); if b then num(R, b) end
  if a.ty == "int" and (not b or b.ty == "int") then return "int" end
  return "long"
end

-- a built-in function: argument count and types, as K.FUNCS gives them
-- the bytes of a value of type ty in a record (LEN of a record or number variable)
local function size_of(R, ty, fixed)
  if fixed then return fixed end
  if K.BYTES[ty] then return K.BYTES[ty] end
  if not K.is_record(ty) then return nil end
  local def, n = R.prog.types[ty:sub(5)], 0
  for _, f in ipairs(def.order) do
    local s = size_of(R, def.fields[f].ty, def.fields[f].fixed)
    if not s then return nil end
    n = n + s
  end
  return n
end

local function builtin(R, e)
  local f, args = K.FUNCS[e.fn], e.args
  if e.fn == "len" and #args == 1 then
    -- LEN of a record or a numeric variable: its size in bytes (for OPEN ... LEN =)
    local a = args[1]
    local ty = expr(R, a)
    if K.is_record(ty) or (NUM_RANK[ty] and (a.k == "var" or a.k == "index" or a.k == "field")) then
      e.bytes = size_of(R, ty, a.fixed)
      if not e.bytes then err(R, "Type mismatch") end
      return "long"
    end
  end
  if e.fn == "lbound" or e.fn == "ubound" then
    args[1].whole = true
    expr(R, args[1])
    if args[2] then num(R, args[2]) end
    return "long"
  end
  for _, a in ipairs(args) do expr(R, a) end
  local nreq, nmax = 0, #f.args
  for _, a in ipairs(f.args) do if a:sub(1, 1) ~= "?" then nreq = nreq + 1 end end
  if #args < nreq or #args > nmax then err(R, "Argument-count mismatch") end
  for i, a in ipairs(args) do
    local want = f.args[i]:gsub("^%?", "")
    if want == "n" then num(R, a) elseif want == "s" then str(R, a) end
  end
  if e.fn == "instr" and args[1].ty == "string" then
    -- INSTR(a$, b$): the optional start is missing
    if #args == 3 then err(R, "Type mismatch") end
    str(R, args[2])
  elseif e.fn == "instr" then
    num(R, args[1]); str(R, args[2])
    if not args[3] then err(R, "Argument-count mismatch") end
    str(R, args[3])
  end
  if f.ty == "float" then return args[1].ty == "double" and "double" or "single" end
  if f.ty == "arg" then return args[1].ty end
  return f.ty
end

local TYPE = {}
function TYPE.num(R, e) return e.ty end
function TYPE.str(R) return "string" end
function TYPE.paren(R, e) return expr(R, e.a) end
function TYPE.var(R, e)
  local dot = e.name:find(".", 1, true)
  if dot and not e.sfx then
    -- p.x where p is a record variable: a field (else p.x is an ordinary name, as in QBasic)
    local base = { k = "var", name = e.name:sub(1, dot - 1), text = e.text:sub(1, dot - 1),
      proc = e.proc, line = e.line, lvalue = e.lvalue }
    if K.is_record(type_of_name(R, base, false)) then
      e.k, e.base, e.path = "field", base, {}
      for f in e.name:sub(dot + 1):gmatch("[^%.]+") do e.path[#e.path + 1] = f end
      return TYPE.field(R, e)
    end
  end
  local c = R.prog.consts[e.name]
  if c and (not e.sfx or TYPE_OF_SUFFIX[e.sfx] == c.ty) then
    if e.lvalue then err(R, "Duplicate definition") end
    e.const = c
    return c.ty
  end
  return type_of_name(R, e, false)
end
function TYPE.index(R, e)
  local ty = type_of_name(R, e, true)
  for _, a in ipairs(e.args) do num(R, a) end
  return ty
end
-- a() is a whole array: an argument of a SUB or FUNCTION, LBOUND or UBOUND, nothing else
-- a field of a record: its TYPE's declaration gives its type (Element not defined if none)
function TYPE.field(R, e)
  local ty = expr(R, e.base)
  for _, f in ipairs(e.path) do
    if not K.is_record(ty) then err(R, "Type mismatch") end
    local field = R.prog.types[ty:sub(5)].fields[f]
    if not field then err(R, "Element not defined") end
    ty, e.fixed = field.ty, field.fixed
  end
  return ty
end
function TYPE.arrayref(R, e)
  if not e.whole then err(R) end
  return type_of_name(R, e, true)
end
local function whole_arrays(R, args)
  for _, a in ipairs(args) do if a.k == "arrayref" then a.whole = true end end
end
local function user_call(R, e)
  if e.k == "ucall" then whole_arrays(R, e.args) end
  for _, a in ipairs(e.args) do expr(R, a) end
  R.calls[#R.calls + 1] = { node = e, line = R.line }
  return fn_result_type(R, e)
end
TYPE.fncall, TYPE.ucall = user_call, user_call
TYPE.call = builtin
function TYPE.neg(R, e) return num(R, e.a).ty end
function TYPE.bin(R, e) expr(R, e.a); expr(R, e.b); return arith_type(R, e.a, e.b, e.op) end
function TYPE.rel(R, e)
  expr(R, e.a); expr(R, e.b)
  if (e.a.ty == "string") ~= (e.b.ty == "string") then err(R, "Type mismatch") end
  return "int"
end
TYPE["not"] = function(R, e) expr(R, e.a); return logic_type(R, e.a) end
function TYPE.logic(R, e) expr(R, e.a); expr(R, e.b); return logic_type(R, e.a, e.b) end
function TYPE.result(R, e) return e.proc.ty end

expr = function(R, e)
  e.ty = TYPE[e.k](R, e)
  return e.ty
end

local function coords(R, p) num(R, p.x); num(R, p.y) end
local function same_kind(R, a, b)
  if (a.ty == "string") ~= (b.ty == "string") then err(R, "Type mismatch") end
  if (K.is_record(a.ty) or K.is_record(b.ty)) and a.ty ~= b.ty then err(R, "Type mismatch") end
end
local function no_record(R, e) if K.is_record(e.ty) then err(R, "Type mismatch") end end

-- ---- statements -------------------------------------------------------------------------
local CHECK = {}
local block

function CHECK.let(R, st) expr(R, st.target); expr(R, st.expr); same_kind(R, st.target, st.expr) end
function CHECK.print(R, st)
  opt_num(R, st.file)
  for _, it in ipairs(st.items) do
    if it.k == "expr" then expr(R, it.e); no_record(R, it.e) elseif it.k == "tab" or it.k == "spc" then num(R, it.e) end
  end
end
function CHECK.rtcall(R, st)
  local sig = K.RT_STATEMENTS[st.fn]
  for i = 1, st.nargs do
    local a = st.args[i]
    if a then if sig:sub(i, i) == "s" then str(R, a) else num(R, a) end end
  end
  for _, a in pairs(st.shape or {}) do num(R, a) end
end
function CHECK.cls(R, st) opt_num(R, st.arg) end
function CHECK.color(R, st) opt_num(R, st.fg); opt_num(R, st.bg); opt_num(R, st.border) end
function CHECK.palette(R, st) opt_num(R, st.attr); opt_num(R, st.color) end
function CHECK.pset(R, st) coords(R, st.p); opt_num(R, st.color) end
CHECK.preset = CHECK.pset
function CHECK.line(R, st)
  if st.p1 then coords(R, st.p1) end
  coords(R, st.p2); opt_num(R, st.color); opt_num(R, st.pattern)
end
function CHECK.circle(R, st)
  coords(R, st.p); num(R, st.r)
  opt_num(R, st.color); opt_num(R, st.a0); opt_num(R, st.a1); opt_num(R, st.aspect)
end
function CHECK.paint(R, st)
  coords(R, st.p)
  if st.color then expr(R, st.color); no_record(R, st.color) end   -- a colour or a tile string
  opt_num(R, st.border)
end
function CHECK.window(R, st)
  if st.p1 then coords(R, st.p1); coords(R, st.p2) end
  opt_num(R, st.fill); opt_num(R, st.border)
end
CHECK.view = CHECK.window
function CHECK.dim(R, st)
  for _, d in ipairs(st.decls) do
    for _, b in ipairs(d.bounds or {}) do opt_num(R, b.lo); num(R, b.hi) end
    if d.as then
      if d.bounds then R.scope.as_array[d.name] = d.as else R.scope.as_scalar[d.name] = d.as end
      if d.bounds then R.scope.fixed_array[d.name] = d.fixed else R.scope.fixed[d.name] = d.fixed end
    end
    if st.k == "static" then R.scope.static[(d.bounds and "()" or "") .. d.name] = true end
    d.ty = type_of_name(R, d, d.bounds ~= nil)
    if st.shared then
      local t = d.bounds and R.prog.shared_arrays or R.prog.shared
      t[d.name] = { as = d.as, fixed = d.fixed }
    end
  end
end
CHECK.static = CHECK.dim
function CHECK.erase(R, st) for _, a in ipairs(st.arrays) do expr(R, a) end end
function CHECK.midset(R, st)
  str(R, st.target); num(R, st.start); opt_num(R, st.len); str(R, st.expr)
end
function CHECK.print_using(R, st)
  opt_num(R, st.file)
  str(R, st.format)
  for _, v in ipairs(st.values) do expr(R, v); no_record(R, v) end
end
function CHECK.const(R, st)
  for _, d in ipairs(st.decls) do
    local n = d.tok
    expr(R, d.expr)
    local ty = n.sfx and TYPE_OF_SUFFIX[n.sfx] or d.expr.ty
    if (ty == "string") ~= (d.expr.ty == "string") then err(R, "Type mismatch") end
    if R.prog.consts[n.v] then err(R, "Duplicate definition") end
    d.const = { name = n.v, ty = ty, text = n.text, line = R.line }
    R.prog.consts[n.v] = d.const
  end
end
function CHECK.read(R, st) for _, t in ipairs(st.targets) do expr(R, t); no_record(R, t) end end
CHECK.input = function(R, st)
  for _, t in ipairs(st.targets) do expr(R, t); no_record(R, t) end
  if st.line_input and st.targets[1].ty ~= "string" then err(R, "Type mismatch") end
end
CHECK["for"] = function(R, st)
  if expr(R, st.var) == "string" then err(R) end
  num(R, st.from); num(R, st.to); opt_num(R, st.step)
  block(R, st.body)
  if st.next_var then
    R.line = st.next_line
    if expr(R, st.next_var) ~= st.var.ty then err(R, "NEXT without FOR") end
  end
end
CHECK["while"] = function(R, st) num(R, st.cond); block(R, st.body) end
CHECK["do"] = function(R, st)
  if st.cond_top then num(R, st.cond_top.e) end
  block(R, st.body)
  if st.cond_bottom then R.line = st.end_line; num(R, st.cond_bottom.e) end
end
function CHECK.ifb(R, st)
  for _, br in ipairs(st.branches) do
    R.line = br.line
    num(R, br.cond)
    block(R, br.body)
  end
  if st.else_body then block(R, st.else_body) end
end
function CHECK.if1(R, st)
  num(R, st.cond)
  block(R, st.then_body)
  if st.else_body then R.line = st.line; block(R, st.else_body) end
end
function CHECK.select(R, st)
  local ty = expr(R, st.expr)
  for _, c in ipairs(st.cases) do
    R.line = c.line
    for _, t in ipairs(c.tests) do
      for _, e in ipairs({ t.e, t.lo, t.hi }) do
        expr(R, e)
        if (ty == "string") ~= (e.ty == "string") then err(R, "Type mismatch") end
      end
    end
    block(R, c.body)
  end
  if st.else_body then block(R, st.else_body) end
end
function CHECK.on(R, st) num(R, st.expr) end
function CHECK.randomize(R, st) num(R, st.expr) end
function CHECK.call(R, st)
  whole_arrays(R, st.args)
  for _, a in ipairs(st.args) do expr(R, a) end
  R.calls[#R.calls + 1] = { node = st, line = R.line, sub = true }
end
-- files: the file numbers are numbers, what is read or written has a type
function CHECK.finput(R, st)
  num(R, st.file)
  CHECK.input(R, st)
end
function CHECK.close(R, st) for _, a in ipairs(st.files) do num(R, a) end end
function CHECK.write(R, st)
  opt_num(R, st.file)
  for _, v in ipairs(st.values) do expr(R, v); no_record(R, v) end
end
function CHECK.frecord(R, st)
  num(R, st.file); opt_num(R, st.record)
  if st.var then expr(R, st.var) end
end
function CHECK.field(R, st)
  num(R, st.file)
  for _, f in ipairs(st.fields) do num(R, f.width); str(R, f.var) end
end
function CHECK.palette_using(R, st)
  st.array.whole = true
  if expr(R, st.array) == "string" then err(R, "Type mismatch") end
  for _, a in ipairs(st.index) do num(R, a) end
end
function CHECK.justify(R, st) str(R, st.target); str(R, st.expr) end
function CHECK.swap(R, st)
  expr(R, st.a); expr(R, st.b)
  if st.a.ty ~= st.b.ty then err(R, "Type mismatch") end
end
function CHECK.deftype(R, st)
  for _, r in ipairs(st.ranges) do
    for c = r[1]:byte(), r[2]:byte() do R.deftype[string.char(c)] = st.ty end
  end
end
function CHECK.shared(R, st)
  for _, item in ipairs(st.names) do
    if item.as then
      if item.array then R.scope.as_array[item.name] = item.as
      else R.scope.as_scalar[item.name] = item.as end
    end
    R.scope.shared[(item.array and "()" or "") .. item.name] = true
  end
end
-- COMMON: the module's variables, with their AS types (and SHARED with every procedure)
function CHECK.common(R, st)
  for _, item in ipairs(st.items) do
    if item.as then
      if item.array then R.scope.as_array[item.name] = item.as
      else R.scope.as_scalar[item.name] = item.as end
      if item.node.sfx then err(R, "Syntax error") end
    end
    if st.shared then
      local t = item.array and R.prog.shared_arrays or R.prog.shared
      t[item.name] = { as = item.as }
    end
    expr(R, item.node)
  end
end
function CHECK.getput(R, st)
  coords(R, st.p1)
  if st.p2 then coords(R, st.p2) end
  for _, a in ipairs(st.index) do num(R, a) end
  st.array.whole = true
  if expr(R, st.array) == "string" then err(R, "Type mismatch") end
end

-- a SUB, FUNCTION or DEF FN: its own scope (DEF FN sees the module's AS types), its
-- result and parameter types
function CHECK.procdef(R, st)
  local proc = st.proc
  R.scope = { kind = proc.kind, as_scalar = {}, as_array = {}, shared = {}, fixed = {},
    fixed_array = {}, static = {} }
  if proc.kind == "deffn" then
    setmetatable(R.scope.as_scalar, { __index = R.main_scope.as_scalar })
    setmetatable(R.scope.as_array, { __index = R.main_scope.as_array })
    setmetatable(R.scope.fixed, { __index = R.main_scope.fixed })
    setmetatable(R.scope.fixed_array, { __index = R.main_scope.fixed_array })
  end
  proc.scope = R.scope
  if proc.kind ~= "sub" then proc.ty = fn_result_type(R, proc) end
  for _, p in ipairs(proc.params) do
    -- a module CONST is visible in every procedure: a parameter may not reuse its name
    if R.prog.consts[p.name] then err(R, "Duplicate definition") end
    if p.as then
      if p.array then R.scope.as_array[p.name] = p.as else R.scope.as_scalar[p.name] = p.as end
    end
    p.ty = p.as or (p.sfx and TYPE_OF_SUFFIX[p.sfx]) or R.deftype[p.name:sub(1, 1)]
  end
  if proc.expr then
    if (proc.ty == "string") ~= (expr(R, proc.expr) == "string") then err(R, "Type mismatch") end
  else
    block(R, proc.tree)
  end
  R.scope = R.main_scope
end

block = function(R, list)
  for _, st in ipairs(list) do
    R.line = st.line
    local f = CHECK[st.k]
    if f then f(R, st) end
  end
end

-- ---- procedures and their calls -----------------------------------------------------------
-- arguments against the parameters: SUB and FUNCTION arguments that are variables are
-- passed by reference and must have the parameter's type
local function check_args(R, proc, args)
  if #args ~= #proc.params then err(R, "Argument-count mismatch") end
  for i, s in ipairs(args) do
    local p = proc.params[i]
    if p.array then
      if s.k ~= "arrayref" or s.ty ~= p.ty then err(R, "Parameter type mismatch") end
    else
      if s.k == "arrayref" then err(R, "Parameter type mismatch") end
      if (p.ty == "string") ~= (s.ty == "string") then err(R, "Type mismatch") end
      if (K.is_record(p.ty) or K.is_record(s.ty)) and s.ty ~= p.ty then
        err(R, "Parameter type mismatch")
      end
      if ((s.k == "var" and not s.const) or s.k == "index") and s.ty ~= p.ty then
        err(R, "Parameter type mismatch")
      end
    end
  end
end

-- the calls collected while checking, against the procedures they name
local function check_calls(R)
  local prog = R.prog
  for _, c in ipairs(R.calls) do
    local e = c.node
    R.line = e.line or c.line
    if e.k == "fncall" then
      local proc = prog.fn_by_name[e.name]
      if not proc then err(R, "Function not defined") end
      if #e.args ~= #proc.params then err(R, "Argument-count mismatch") end
      for i, a in ipairs(e.args) do
        if (proc.params[i].ty == "string") ~= (a.ty == "string") then err(R, "Type mismatch") end
      end
    else
      local proc = prog.proc_by_name[e.name]
      local want = c.sub and "sub" or "function"
      if not proc or proc.kind ~= want then err(R, "Subprogram not defined") end
      e.callee = proc
      check_args(R, proc, e.args)
    end
  end
end

function M.resolve(prog)
  prog.consts, prog.shared, prog.shared_arrays = {}, {}, {}
  -- the resolver's state: the scope of the statement being checked and its line
  local R = { prog = prog, deftype = {}, line = 0, calls = {},
    main_scope = { kind = "main", as_scalar = {}, as_array = {}, shared = {}, fixed = {},
      fixed_array = {}, static = {} } }
  for c = string.byte("a"), string.byte("z") do R.deftype[string.char(c)] = "single" end
  R.scope = R.main_scope

  local proc_by_name, fn_by_name = {}, {}
  for _, proc in ipairs(prog.procs) do
    local t = proc.kind == "deffn" and fn_by_name or proc_by_name
    if t[proc.name] then qerr("Duplicate definition", proc.line) end
    t[proc.name] = proc
  end
  prog.proc_by_name, prog.fn_by_name = proc_by_name, fn_by_name

  block(R, prog.main)
  prog.main_scope = R.main_scope
  check_calls(R)
  return prog
end

return M
