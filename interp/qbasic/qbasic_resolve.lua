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

function M.resolve(prog)
  prog.consts, prog.shared, prog.shared_arrays = {}, {}, {}
  local deftype = {}
  for c = string.byte("a"), string.byte("z") do deftype[string.char(c)] = "single" end
  local main_scope = { kind = "main", as_scalar = {}, as_array = {}, shared = {}, fixed = {},
    fixed_array = {}, static = {} }
  local scope = main_scope
  local line = 0             -- the line of the statement being checked
  local calls = {}           -- calls of procedures, checked when every signature is known

  local function err(msg) qerr(msg, line) end

  -- ---- types of names ---------------------------------------------------------------------
  local function type_of_name(n, is_array)
    if n.sfx then return TYPE_OF_SUFFIX[n.sfx] end
    local as = is_array and scope.as_array or scope.as_scalar
    if as[n.name] then
      -- a fixed-length string (DIM s AS STRING * 8): stores pad or cut it to its length
      n.fixed = (is_array and scope.fixed_array or scope.fixed)[n.name]
      return as[n.name]
    end
    if scope ~= main_scope then
      local sas = is_array and prog.shared_arrays or prog.shared
      if sas[n.name] and sas[n.name].as then
        n.fixed = sas[n.name].fixed
        return sas[n.name].as
      end
    end
    return deftype[n.name:sub(1, 1)]
  end
  local function fn_result_type(n)
    if n.sfx then return TYPE_OF_SUFFIX[n.sfx] end
    return deftype[n.name:sub(1, 1)]
  end

  -- ---- expressions ------------------------------------------------------------------------
  local expr
  local function num(e) if not NUM_RANK[expr(e)] then err("Type mismatch") end return e end
  local function str(e) if expr(e) ~= "string" then err("Type mismatch") end return e end
  local function opt_num(e) if e then num(e) end end

  local function arith_type(a, b, op)
    if K.is_record(a.ty) or K.is_record(b.ty) then err("Type mismatch") end
    if a.ty == "string" or b.ty == "string" then
      if op == "+" and a.ty == "string" and b.ty == "string" then return "string" end
      err("Type mismatch")
    end
    local r = NUM_RANK[a.ty] >= NUM_RANK[b.ty] and a.ty or b.ty
    if op == "/" and (r == "int" or r == "long") then r = "single" end
    if op == "^" then r = (r == "double") and "double" or "single" end
    if op == "\\" or op == "mod" then r = (a.ty == "int" and b.ty == "int") and "int" or "long" end
    return r
  end
  local function logic_type(a, b)
    num(a); if b then num(b) end
    if a.ty == "int" and (not b or b.ty == "int") then return "int" end
    return "long"
  end

  -- a built-in function: argument count and types, as K.FUNCS gives them
  local function builtin(e)
    local f, args = K.FUNCS[e.fn], e.args
    if e.fn == "lbound" or e.fn == "ubound" then
      args[1].whole = true
      expr(args[1])
      if args[2] then num(args[2]) end
      return "long"
    end
    for _, a in ipairs(args) do expr(a) end
    local nreq, nmax = 0, #f.args
    for _, a in ipairs(f.args) do if a:sub(1, 1) ~= "?" then nreq = nreq + 1 end end
    if #args < nreq or #args > nmax then err("Argument-count mismatch") end
    for i, a in ipairs(args) do
      local want = f.args[i]:gsub("^%?", "")
      if want == "n" then num(a) elseif want == "s" then str(a) end
    end
    if e.fn == "instr" and args[1].ty == "string" then
      -- INSTR(a$, b$): the optional start is missing
      if #args == 3 then err("Type mismatch") end
      str(args[2])
    elseif e.fn == "instr" then
      num(args[1]); str(args[2])
      if not args[3] then err("Argument-count mismatch") end
      str(args[3])
    end
    if f.ty == "float" then return args[1].ty == "double" and "double" or "single" end
    if f.ty == "arg" then return args[1].ty end
    return f.ty
  end

  local TYPE = {}
  function TYPE.num(e) return e.ty end
  function TYPE.str() return "string" end
  function TYPE.paren(e) return expr(e.a) end
  function TYPE.var(e)
    local dot = e.name:find(".", 1, true)
    if dot and not e.sfx then
      -- p.x where p is a record variable: a field (else p.x is an ordinary name, as in QBasic)
      local base = { k = "var", name = e.name:sub(1, dot - 1), text = e.text:sub(1, dot - 1),
        proc = e.proc, line = e.line, lvalue = e.lvalue }
      if K.is_record(type_of_name(base, false)) then
        e.k, e.base, e.path = "field", base, {}
        for f in e.name:sub(dot + 1):gmatch("[^%.]+") do e.path[#e.path + 1] = f end
        return TYPE.field(e)
      end
    end
    local c = prog.consts[e.name]
    if c and (not e.sfx or TYPE_OF_SUFFIX[e.sfx] == c.ty) then
      if e.lvalue then err("Duplicate definition") end
      e.const = c
      return c.ty
    end
    return type_of_name(e, false)
  end
  function TYPE.index(e)
    local ty = type_of_name(e, true)
    for _, a in ipairs(e.args) do num(a) end
    return ty
  end
  -- a() is a whole array: an argument of a SUB or FUNCTION, LBOUND or UBOUND, nothing else
  -- a field of a record: its TYPE's declaration gives its type (Element not defined if none)
  function TYPE.field(e)
    local ty = expr(e.base)
    for _, f in ipairs(e.path) do
      if not K.is_record(ty) then err("Type mismatch") end
      local field = prog.types[ty:sub(5)].fields[f]
      if not field then err("Element not defined") end
      ty, e.fixed = field.ty, field.fixed
    end
    return ty
  end
  function TYPE.arrayref(e)
    if not e.whole then err() end
    return type_of_name(e, true)
  end
  local function whole_arrays(args)
    for _, a in ipairs(args) do if a.k == "arrayref" then a.whole = true end end
  end
  local function user_call(e)
    if e.k == "ucall" then whole_arrays(e.args) end
    for _, a in ipairs(e.args) do expr(a) end
    calls[#calls + 1] = { node = e, line = line }
    return fn_result_type(e)
  end
  TYPE.fncall, TYPE.ucall = user_call, user_call
  TYPE.call = builtin
  function TYPE.neg(e) return num(e.a).ty end
  function TYPE.bin(e) expr(e.a); expr(e.b); return arith_type(e.a, e.b, e.op) end
  function TYPE.rel(e)
    expr(e.a); expr(e.b)
    if (e.a.ty == "string") ~= (e.b.ty == "string") then err("Type mismatch") end
    return "int"
  end
  TYPE["not"] = function(e) expr(e.a); return logic_type(e.a) end
  function TYPE.logic(e) expr(e.a); expr(e.b); return logic_type(e.a, e.b) end
  function TYPE.result(e) return e.proc.ty end

  expr = function(e)
    e.ty = TYPE[e.k](e)
    return e.ty
  end
  M.expr = expr

  local function coords(p) num(p.x); num(p.y) end
  local function same_kind(a, b)
    if (a.ty == "string") ~= (b.ty == "string") then err("Type mismatch") end
    if (K.is_record(a.ty) or K.is_record(b.ty)) and a.ty ~= b.ty then err("Type mismatch") end
  end
  local function no_record(e) if K.is_record(e.ty) then err("Type mismatch") end end

  -- ---- statements -------------------------------------------------------------------------
  local CHECK = {}
  local block

  function CHECK.let(st) expr(st.target); expr(st.expr); same_kind(st.target, st.expr) end
  function CHECK.print(st)
    for _, it in ipairs(st.items) do
      if it.k == "expr" then expr(it.e); no_record(it.e) elseif it.k == "tab" or it.k == "spc" then num(it.e) end
    end
  end
  function CHECK.rtcall(st)
    local sig = K.RT_STATEMENTS[st.fn]
    for i = 1, st.nargs do
      local a = st.args[i]
      if a then if sig:sub(i, i) == "s" then str(a) else num(a) end end
    end
    for _, a in pairs(st.shape or {}) do num(a) end
  end
  function CHECK.cls(st) opt_num(st.arg) end
  function CHECK.color(st) opt_num(st.fg); opt_num(st.bg) end
  function CHECK.palette(st) opt_num(st.attr); opt_num(st.color) end
  function CHECK.pset(st) coords(st.p); opt_num(st.color) end
  CHECK.preset = CHECK.pset
  function CHECK.line(st)
    if st.p1 then coords(st.p1) end
    coords(st.p2); opt_num(st.color); opt_num(st.pattern)
  end
  function CHECK.circle(st)
    coords(st.p); num(st.r)
    opt_num(st.color); opt_num(st.a0); opt_num(st.a1); opt_num(st.aspect)
  end
  function CHECK.paint(st)
    coords(st.p)
    if st.color then expr(st.color); no_record(st.color) end   -- a colour or a tile string
    opt_num(st.border)
  end
  function CHECK.window(st)
    if st.p1 then coords(st.p1); coords(st.p2) end
    opt_num(st.fill); opt_num(st.border)
  end
  CHECK.view = CHECK.window
  function CHECK.dim(st)
    for _, d in ipairs(st.decls) do
      for _, b in ipairs(d.bounds or {}) do opt_num(b.lo); num(b.hi) end
      if d.as then
        if d.bounds then scope.as_array[d.name] = d.as else scope.as_scalar[d.name] = d.as end
        if d.bounds then scope.fixed_array[d.name] = d.fixed else scope.fixed[d.name] = d.fixed end
      end
      if st.k == "static" then scope.static[(d.bounds and "()" or "") .. d.name] = true end
      d.ty = type_of_name(d, d.bounds ~= nil)
      if st.shared then
        local t = d.bounds and prog.shared_arrays or prog.shared
        t[d.name] = { as = d.as, fixed = d.fixed }
      end
    end
  end
  CHECK.static = CHECK.dim
  function CHECK.erase(st) for _, a in ipairs(st.arrays) do expr(a) end end
  function CHECK.midset(st)
    str(st.target); num(st.start); opt_num(st.len); str(st.expr)
  end
  function CHECK.print_using(st)
    str(st.format)
    for _, v in ipairs(st.values) do expr(v); no_record(v) end
  end
  function CHECK.const(st)
    for _, d in ipairs(st.decls) do
      local n = d.tok
      expr(d.expr)
      local ty = n.sfx and TYPE_OF_SUFFIX[n.sfx] or d.expr.ty
      if (ty == "string") ~= (d.expr.ty == "string") then err("Type mismatch") end
      if prog.consts[n.v] then err("Duplicate definition") end
      d.const = { name = n.v, ty = ty, text = n.text, line = line }
      prog.consts[n.v] = d.const
    end
  end
  function CHECK.read(st) for _, t in ipairs(st.targets) do expr(t); no_record(t) end end
  CHECK.input = function(st)
    for _, t in ipairs(st.targets) do expr(t); no_record(t) end
    if st.line_input and st.targets[1].ty ~= "string" then err("Type mismatch") end
  end
  CHECK["for"] = function(st)
    if expr(st.var) == "string" then err() end
    num(st.from); num(st.to); opt_num(st.step)
    block(st.body)
    if st.next_var then
      line = st.next_line
      if expr(st.next_var) ~= st.var.ty then err("NEXT without FOR") end
    end
  end
  CHECK["while"] = function(st) num(st.cond); block(st.body) end
  CHECK["do"] = function(st)
    if st.cond_top then num(st.cond_top.e) end
    block(st.body)
    if st.cond_bottom then line = st.end_line; num(st.cond_bottom.e) end
  end
  function CHECK.ifb(st)
    for _, br in ipairs(st.branches) do
      line = br.line
      num(br.cond)
      block(br.body)
    end
    if st.else_body then block(st.else_body) end
  end
  function CHECK.if1(st)
    num(st.cond)
    block(st.then_body)
    if st.else_body then line = st.line; block(st.else_body) end
  end
  function CHECK.select(st)
    local ty = expr(st.expr)
    for _, c in ipairs(st.cases) do
      line = c.line
      for _, t in ipairs(c.tests) do
        for _, e in ipairs({ t.e, t.lo, t.hi }) do
          expr(e)
          if (ty == "string") ~= (e.ty == "string") then err("Type mismatch") end
        end
      end
      block(c.body)
    end
    if st.else_body then block(st.else_body) end
  end
  function CHECK.on(st) num(st.expr) end
  function CHECK.randomize(st) num(st.expr) end
  function CHECK.call(st)
    whole_arrays(st.args)
    for _, a in ipairs(st.args) do expr(a) end
    calls[#calls + 1] = { node = st, line = line, sub = true }
  end
  function CHECK.swap(st)
    expr(st.a); expr(st.b)
    if st.a.ty ~= st.b.ty then err("Type mismatch") end
  end
  function CHECK.deftype(st)
    for _, r in ipairs(st.ranges) do
      for c = r[1]:byte(), r[2]:byte() do deftype[string.char(c)] = st.ty end
    end
  end
  function CHECK.shared(st)
    for _, item in ipairs(st.names) do
      if item.as then
        if item.array then scope.as_array[item.name] = item.as
        else scope.as_scalar[item.name] = item.as end
      end
      scope.shared[(item.array and "()" or "") .. item.name] = true
    end
  end
  function CHECK.getput(st)
    coords(st.p1)
    if st.p2 then coords(st.p2) end
    for _, a in ipairs(st.index) do num(a) end
    st.array.whole = true
    if expr(st.array) == "string" then err("Type mismatch") end
  end

  -- a SUB, FUNCTION or DEF FN: its own scope (DEF FN sees the module's AS types), its
  -- result and parameter types
  function CHECK.procdef(st)
    local proc = st.proc
    scope = { kind = proc.kind, as_scalar = {}, as_array = {}, shared = {}, fixed = {},
      fixed_array = {}, static = {} }
    if proc.kind == "deffn" then
      setmetatable(scope.as_scalar, { __index = main_scope.as_scalar })
      setmetatable(scope.as_array, { __index = main_scope.as_array })
      setmetatable(scope.fixed, { __index = main_scope.fixed })
      setmetatable(scope.fixed_array, { __index = main_scope.fixed_array })
    end
    proc.scope = scope
    if proc.kind ~= "sub" then proc.ty = fn_result_type(proc) end
    for _, p in ipairs(proc.params) do
      -- a module CONST is visible in every procedure: a parameter may not reuse its name
      if prog.consts[p.name] then err("Duplicate definition") end
      if p.as then
        if p.array then scope.as_array[p.name] = p.as else scope.as_scalar[p.name] = p.as end
      end
      p.ty = p.as or (p.sfx and TYPE_OF_SUFFIX[p.sfx]) or deftype[p.name:sub(1, 1)]
    end
    if proc.expr then
      if (proc.ty == "string") ~= (expr(proc.expr) == "string") then err("Type mismatch") end
    else
      block(proc.tree)
    end
    scope = main_scope
  end

  block = function(list)
    for _, st in ipairs(list) do
      line = st.line
      local f = CHECK[st.k]
      if f then f(st) end
    end
  end

  -- ---- procedures and their calls -----------------------------------------------------------
  local proc_by_name, fn_by_name = {}, {}
  for _, proc in ipairs(prog.procs) do
    local t = proc.kind == "deffn" and fn_by_name or proc_by_name
    if t[proc.name] then qerr("Duplicate definition", proc.line) end
    t[proc.name] = proc
  end
  prog.proc_by_name, prog.fn_by_name = proc_by_name, fn_by_name

  block(prog.main)
  prog.main_scope = main_scope

  -- arguments against the parameters: SUB and FUNCTION arguments that are variables are
  -- passed by reference and must have the parameter's type
  local function check_args(proc, args)
    if #args ~= #proc.params then err("Argument-count mismatch") end
    for i, s in ipairs(args) do
      local p = proc.params[i]
      if p.array then
        if s.k ~= "arrayref" or s.ty ~= p.ty then err("Parameter type mismatch") end
      else
        if s.k == "arrayref" then err("Parameter type mismatch") end
        if (p.ty == "string") ~= (s.ty == "string") then err("Type mismatch") end
        if (K.is_record(p.ty) or K.is_record(s.ty)) and s.ty ~= p.ty then
          err("Parameter type mismatch")
        end
        if ((s.k == "var" and not s.const) or s.k == "index") and s.ty ~= p.ty then
          err("Parameter type mismatch")
        end
      end
    end
  end
  for _, c in ipairs(calls) do
    local e = c.node
    line = e.line or c.line
    if e.k == "fncall" then
      local proc = fn_by_name[e.name]
      if not proc then err("Function not defined") end
      if #e.args ~= #proc.params then err("Argument-count mismatch") end
      for i, a in ipairs(e.args) do
        if (proc.params[i].ty == "string") ~= (a.ty == "string") then err("Type mismatch") end
      end
    else
      local proc = proc_by_name[e.name]
      local want = c.sub and "sub" or "function"
      if not proc or proc.kind ~= want then err("Subprogram not defined") end
      e.callee = proc
      check_args(proc, e.args)
    end
  end
  return prog
end

return M
