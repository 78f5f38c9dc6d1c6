-- QBasic front end, part 2: the parser.  Source lines -> statements with types resolved.
--
-- parse(source) returns a program:
--   lines      the physical source lines
--   main       the module-level statements in order (flat: FOR, NEXT, IF-block parts... are
--              separate statements; qbasic_block builds the tree), with {k="procdef"} at the
--              place of each SUB, FUNCTION and DEF FN
--   procs      list of procedures {kind="sub"|"function"|"deffn", name, params, body(flat)}
--   data       DATA items in order {text, quoted, line}
--   data_labels  label -> index of the first DATA item at or after it
--   labels     label -> {line, proc}
-- Every statement has .line (its physical line).  Errors are raised as {qb=true, msg, line}.
local lex = require "qbasic_lex"

local M = {}

local TYPE_OF_SUFFIX = { ["%"] = "int", ["&"] = "long", ["!"] = "single", ["#"] = "double",
  ["$"] = "string" }
local SUFFIX_OF_TYPE = { int = "%", long = "&", single = "!", double = "#", string = "$" }
M.SUFFIX_OF_TYPE = SUFFIX_OF_TYPE
local AS_TYPES = { integer = "int", long = "long", single = "single", double = "double",
  string = "string" }
local NUM_RANK = { int = 1, long = 2, single = 3, double = 4 }

-- ---- built-in functions ------------------------------------------------------------------
-- args: list of argument types ("n" number, "s" string), a "?" prefix marks optional ones.
-- ty: result type, or "arg" (the type of the first argument), or "float" (single, or double
-- when the argument is double).
local FUNCS = {
  sin = { args = { "n" }, ty = "float" }, cos = { args = { "n" }, ty = "float" },
  tan = { args = { "n" }, ty = "float" }, atn = { args = { "n" }, ty = "float" },
  sqr = { args = { "n" }, ty = "float" }, exp = { args = { "n" }, ty = "float" },
  log = { args = { "n" }, ty = "float" }, abs = { args = { "n" }, ty = "arg" },
  int = { args = { "n" }, ty = "arg" }, fix = { args = { "n" }, ty = "arg" },
  sgn = { args = { "n" }, ty = "int" }, cint = { args = { "n" }, ty = "int" },
  clng = { args = { "n" }, ty = "long" }, csng = { args = { "n" }, ty = "single" },
  cdbl = { args = { "n" }, ty = "double" }, rnd = { args = { "?n" }, ty = "single" },
  timer = { args = {}, ty = "single" },
  len = { args = { "s" }, ty = "long" }, ["left$"] = { args = { "s", "n" }, ty = "string" },
  ["right$"] = { args = { "s", "n" }, ty = "string" },
  ["mid$"] = { args = { "s", "n", "?n" }, ty = "string" },
  ["str$"] = { args = { "n" }, ty = "string" }, val = { args = { "s" }, ty = "double" },
  ["chr$"] = { args = { "n" }, ty = "string" }, asc = { args = { "s" }, ty = "int" },
  ["space$"] = { args = { "n" }, ty = "string" },
  ["string$"] = { args = { "n", "x" }, ty = "string" },
  ["lcase$"] = { args = { "s" }, ty = "string" }, ["ucase$"] = { args = { "s" }, ty = "string" },
  ["ltrim$"] = { args = { "s" }, ty = "string" }, ["rtrim$"] = { args = { "s" }, ty = "string" },
  instr = { args = { "x", "s", "?s" }, ty = "long" },
  ["hex$"] = { args = { "n" }, ty = "string" }, ["oct$"] = { args = { "n" }, ty = "string" },
  point = { args = { "n", "?n" }, ty = "int" },
  -- the screen and the keyboard (docs/qbasic.md, "Programs that expect a person")
  ["inkey$"] = { args = {}, ty = "string" }, ["input$"] = { args = { "n", "?n" }, ty = "string" },
  csrlin = { args = {}, ty = "int" }, pos = { args = { "n" }, ty = "int" },
  pmap = { args = { "n", "n" }, ty = "single" }, ["varptr$"] = { args = { "x" }, ty = "string" },
  lbound = { args = { "arr", "?n" }, ty = "long" }, ubound = { args = { "arr", "?n" }, ty = "long" },
}
M.FUNCS = FUNCS

-- statements pointcalc knows but does not implement: named in the error
local function unsupported(what, line)
  error({ qb = true, msg = what .. ": not supported by pointcalc", line = line }, 0)
end

local function numeric(ty) return NUM_RANK[ty] ~= nil end

function M.parse(source, opts)
  opts = opts or {}
  local lines = {}
  source = source:gsub("^\239\187\191", "")     -- a UTF-8 byte-order mark
  for l in (source .. "\n"):gmatch("([^\n]*)\n") do
    lines[#lines + 1] = l:gsub("\r", "")
  end
  if source:sub(-1) == "\n" then lines[#lines] = nil end
  if #lines == 0 then lines[1] = "" end

  local prog = { lines = lines, main = {}, procs = {}, data = {}, data_labels = {}, labels = {},
    label_list = {}, option_base = 0, consts = {}, shared = {}, shared_arrays = {} }

  -- DEFtype letters
  local deftype = {}
  for c = string.byte("a"), string.byte("z") do deftype[string.char(c)] = "single" end

  local lineno = 0
  local toks, pos = nil, 1

  local function err(msg, line)
    error({ qb = true, msg = msg or "Syntax error", line = line or lineno }, 0)
  end
  local function peek(o) return toks[pos + (o or 0)] end
  local function nexttok() local t = toks[pos]; pos = pos + 1; return t end
  local function is_op(v, o) local t = toks[pos + (o or 0)]; return t.t == "op" and t.v == v end
  local function is_kw(v, o) local t = toks[pos + (o or 0)]; return t.t == "kw" and t.v == v end
  local function accept_op(v) if is_op(v) then pos = pos + 1; return true end end
  local function accept_kw(v) if is_kw(v) then pos = pos + 1; return true end end
  local function expect_op(v) if not accept_op(v) then err() end end
  local function expect_kw(v) if not accept_kw(v) then err() end end
  local function at_end()   -- end of a statement
    local t = toks[pos]
    return t.t == "eol" or (t.t == "op" and t.v == ":") or (t.t == "kw" and t.v == "else")
  end

  -- ---- procedures known in advance (FUNCTION names decide calls vs arrays) ---------------
  local functions, subs = {}, {}
  local all_toks = {}
  for i, l in ipairs(lines) do
    local ok, t = pcall(lex.line, l)
    if not ok then
      if type(t) == "table" and t.qb then t.line = i; error(t, 0) end
      error(t, 0)
    end
    all_toks[i] = t
    for j = 1, #t - 1 do
      local a, b = t[j], t[j + 1]
      if a.t == "kw" and (a.v == "function" or a.v == "sub") and b.t == "id"
          and (j == 1 or t[j - 1].t == "kw" and t[j - 1].v == "declare" or t[j - 1].t == "num") then
        if a.v == "function" then functions[b.v] = b else subs[b.v] = b end
      end
    end
  end
  prog.functions, prog.subs = functions, subs

  -- ---- scopes and symbols -------------------------------------------------------------------
  local main_scope = { kind = "main", as_scalar = {}, as_array = {}, arrays = {}, params = {} }
  local scope = main_scope
  local cur_proc = nil                 -- the procedure being parsed, or nil
  local body = prog.main               -- where statements go

  local function type_of_name(tok, is_array)
    if tok.sfx then return TYPE_OF_SUFFIX[tok.sfx] end
    local as = is_array and scope.as_array or scope.as_scalar
    if as[tok.v] then return as[tok.v] end
    if scope ~= main_scope then
      local sas = is_array and prog.shared_arrays or prog.shared
      if sas[tok.v] and sas[tok.v].as then return sas[tok.v].as end
    end
    return deftype[tok.v:sub(1, 1)]
  end

  -- a scalar variable (or CONST) reference
  local function var_node(tok)
    local c = prog.consts[tok.v]
    if c and (not tok.sfx or TYPE_OF_SUFFIX[tok.sfx] == c.ty) then
      return { k = "var", name = tok.v, ty = c.ty, const = c, text = tok.text, proc = cur_proc,
        line = lineno }
    end
    local ty = type_of_name(tok, false)
    return { k = "var", name = tok.v, ty = ty, text = tok.text, proc = cur_proc, line = lineno }
  end

  local parse_expr

  local function parse_args()
    local args = {}
    if accept_op(")") then return args end
    repeat args[#args + 1] = parse_expr() until not accept_op(",")
    expect_op(")")
    return args
  end

  local function check_num(e)
    if not numeric(e.ty) then err("Type mismatch") end
    return e
  end
  local function check_str(e)
    if e.ty ~= "string" then err("Type mismatch") end
    return e
  end

  local function array_node(tok, args)
    local ty = type_of_name(tok, true)
    for _, a in ipairs(args) do check_num(a) end
    return { k = "index", name = tok.v, ty = ty, args = args, text = tok.text, proc = cur_proc,
      line = lineno }
  end

  local function fn_result_type(tok)
    if tok.sfx then return TYPE_OF_SUFFIX[tok.sfx] end
    return deftype[tok.v:sub(1, 1)]
  end

  local function parse_atom()
    local t = peek()
    if t.t == "num" then
      pos = pos + 1
      if t.overflow then err("Overflow") end
      return { k = "num", v = t.v, ty = t.ty, text = t.text }
    elseif t.t == "str" then
      pos = pos + 1
      return { k = "str", v = t.v, ty = "string" }
    elseif t.t == "op" and t.v == "(" then
      pos = pos + 1
      local e = parse_expr()
      expect_op(")")
      return { k = "paren", a = e, ty = e.ty }
    elseif t.t == "id" then
      pos = pos + 1
      local fname = t.v
      if fname:sub(1, 2) == "fn" then            -- DEF FN call
        local args = {}
        if accept_op("(") then args = parse_args() end
        return { k = "fncall", name = fname, args = args, ty = fn_result_type(t), text = t.text,
          line = lineno }
      end
      if functions[fname] then
        local args = {}
        if accept_op("(") then args = parse_args() end
        -- inside FUNCTION f, a bare f is a recursive call only with parentheses or if f has
        -- no parameters; QBasic treats "f" as the result variable on the left of "=" only
        return { k = "ucall", name = fname, args = args, ty = fn_result_type(t), text = t.text,
          line = lineno }
      end
      if is_op("(") then
        if is_op(")", 1) then        -- a() : a whole array, as an argument
          pos = pos + 2
          return { k = "arrayref", name = t.v, ty = type_of_name(t, true), text = t.text,
            proc = cur_proc }
        end
        pos = pos + 1
        local args = parse_args()
        return array_node(t, args)
      end
      return var_node(t)
    elseif t.t == "kw" then
      local f = FUNCS[t.v]
      if not f then
        if t.v == "inkey$" or t.v == "input$" or t.v == "date$" or t.v == "time$"
            or t.v == "csrlin" or t.v == "pos" or t.v == "peek" or t.v == "inp" or t.v == "eof"
            or t.v == "pmap" or t.v == "fre" or t.v == "varptr" or t.v == "environ$"
            or t.v == "err" or t.v == "erl" or t.v == "lof" or t.v == "loc" or t.v == "freefile"
            or t.v == "cvi" or t.v == "cvs" or t.v == "cvl" or t.v == "cvd" or t.v == "mki$"
            or t.v == "mks$" or t.v == "mkl$" or t.v == "mkd$" or t.v == "stick" or t.v == "strig"
            or t.v == "pen" or t.v == "play" or t.v == "screen" or t.v == "sadd" or t.v == "lpos"
            or t.v == "ioctl$" or t.v == "fileattr" or t.v == "seek" or t.v == "varseg"
            or t.v == "varptr$" or t.v == "erdev" or t.v == "erdev$" or t.v == "shell"
            or t.v == "command$" then
          unsupported(t.v:upper() .. " function", lineno)
        end
        err()
      end
      pos = pos + 1
      local args = {}
      if t.v == "lbound" or t.v == "ubound" then
        expect_op("(")
        local a = nexttok()
        if a.t ~= "id" then err() end
        local arr = { k = "arrayref", name = a.v, ty = type_of_name(a, true), text = a.text,
          proc = cur_proc }
        args[1] = arr
        if accept_op(",") then args[2] = check_num(parse_expr()) end
        expect_op(")")
        return { k = "call", fn = t.v, args = args, ty = "long" }
      end
      if accept_op("(") then
        args = parse_args()
      end
      -- argument count and types
      local nreq, nmax = 0, #f.args
      for _, a in ipairs(f.args) do if a:sub(1, 1) ~= "?" then nreq = nreq + 1 end end
      if #args < nreq or #args > nmax then err("Argument-count mismatch") end
      for i, a in ipairs(args) do
        local want = f.args[i]:gsub("^%?", "")
        if want == "n" then check_num(a) elseif want == "s" then check_str(a) end
      end
      if t.v == "instr" and args[1].ty == "string" then
        -- INSTR(a$, b$): the optional start is missing
        if #args == 3 then err("Type mismatch") end
        check_str(args[2])
      elseif t.v == "instr" then
        check_num(args[1]); check_str(args[2])
        if not args[3] then err("Argument-count mismatch") end
        check_str(args[3])
      end
      local ty = f.ty
      if ty == "float" then ty = args[1].ty == "double" and "double" or "single"
      elseif ty == "arg" then ty = args[1].ty end
      return { k = "call", fn = t.v, args = args, ty = ty }
    elseif t.t == "op" and t.v == "-" then
      err()
    end
    err()
  end

  local function arith_type(a, b, op)
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
    check_num(a); if b then check_num(b) end
    if a.ty == "int" and (not b or b.ty == "int") then return "int" end
    return "long"
  end

  -- unary - and + in front of what `operand` parses; QBasic also allows them right after ^
  -- (2 ^ -1), where they apply to the exponent only
  local function signed(operand)
    local function parse()
      if accept_op("-") then
        local a = parse()
        check_num(a)
        return { k = "neg", a = a, ty = a.ty }
      end
      if accept_op("+") then return parse() end
      return operand()
    end
    return parse
  end
  local parse_pow_operand = signed(parse_atom)
  local function parse_pow()
    local a = parse_atom()
    while is_op("^") do
      pos = pos + 1
      local b = parse_pow_operand()
      a = { k = "bin", op = "^", a = a, b = b, ty = arith_type(a, b, "^") }
    end
    return a
  end
  local parse_unary = signed(parse_pow)
  local function binary_level(sub, ops)
    return function()
      local a = sub()
      while true do
        local t = peek()
        local op
        if t.t == "op" and ops[t.v] then op = t.v
        elseif t.t == "kw" and ops[t.v] then op = t.v end
        if not op then return a end
        pos = pos + 1
        local b = sub()
        a = { k = "bin", op = op, a = a, b = b, ty = arith_type(a, b, op) }
      end
    end
  end
  local parse_mul = binary_level(parse_unary, { ["*"] = true, ["/"] = true })
  local parse_idiv = binary_level(parse_mul, { ["\\"] = true })
  local parse_mod = binary_level(parse_idiv, { mod = true })
  local parse_add = binary_level(parse_mod, { ["+"] = true, ["-"] = true })
  local RELOPS = { ["="] = true, ["<>"] = true, ["<"] = true, [">"] = true, ["<="] = true,
    [">="] = true }
  local function parse_rel()
    local a = parse_add()
    while peek().t == "op" and RELOPS[peek().v] do
      local op = nexttok().v
      local b = parse_add()
      if (a.ty == "string") ~= (b.ty == "string") then err("Type mismatch") end
      a = { k = "rel", op = op, a = a, b = b, ty = "int" }
    end
    return a
  end
  local function parse_not()
    if accept_kw("not") then
      local a = parse_not()
      return { k = "not", a = a, ty = logic_type(a) }
    end
    return parse_rel()
  end
  local function logic_level(sub, word)
    return function()
      local a = sub()
      while is_kw(word) do
        pos = pos + 1
        local b = sub()
        a = { k = "logic", op = word, a = a, b = b, ty = logic_type(a, b) }
      end
      return a
    end
  end
  local parse_and = logic_level(parse_not, "and")
  local parse_or = logic_level(parse_and, "or")
  local parse_xor = logic_level(parse_or, "xor")
  local parse_eqv = logic_level(parse_xor, "eqv")
  local parse_imp = logic_level(parse_eqv, "imp")
  parse_expr = parse_imp
  M.NUM_RANK = NUM_RANK

  -- ---- statements ---------------------------------------------------------------------------
  local function add(st)
    st.line = st.line or lineno
    body[#body + 1] = st
    return st
  end

  -- an assignable reference: variable or array element
  local function parse_lvalue()
    local t = nexttok()
    if t.t ~= "id" then err() end
    if t.v:sub(1, 2) == "fn" and cur_proc and cur_proc.kind == "deffn" and cur_proc.name == t.v then
      return { k = "result", name = t.v, ty = cur_proc.ty, proc = cur_proc }
    end
    if functions[t.v] then
      if cur_proc and cur_proc.kind == "function" and cur_proc.name == t.v then
        return { k = "result", name = t.v, ty = cur_proc.ty, proc = cur_proc }
      end
      err("Duplicate definition")
    end
    if is_op("(") then
      pos = pos + 1
      local args = parse_args()
      if #args == 0 then err() end
      return array_node(t, args)
    end
    local v = var_node(t)
    if v.const then err("Duplicate definition") end
    return v
  end

  local function label_name(t)
    -- QBasic's line numbers are 0..65529
    if t.t == "num" and (t.ty == "int" or t.ty == "long" or t.ty == "single" or t.ty == "double")
        and t.v == math.floor(t.v) and t.v >= 0 and t.v <= 65529 then
      return string.format("%d", t.v)
    elseif t.t == "id" and not t.sfx then
      return t.v
    end
    err()
  end

  local parse_statement

  -- statements up to the end of the line, or up to ELSE (single-line IF)
  local function parse_stmt_list(list, stop_at_else)
    -- list: where the statements go (a single-line IF branch), or nil for the current body
    -- (a SUB or FUNCTION line switches the current body)
    local saved = body
    if list then body = list end
    while true do
      local t = peek()
      if t.t == "eol" then break end
      if t.t == "kw" and t.v == "else" then
        if stop_at_else then break end
        -- ELSE of a block IF: a statement of its own, possibly followed by more on the line
        pos = pos + 1
        add({ k = "else" })
        goto continue
      end
      if t.t == "op" and t.v == ":" then
        pos = pos + 1
      else
        parse_statement(stop_at_else)
        local t2 = peek()
        if not (t2.t == "eol" or (t2.t == "op" and t2.v == ":") or (t2.t == "kw" and t2.v == "else"
            and stop_at_else)) then
          err()
        end
      end
      ::continue::
    end
    if list then body = saved end
  end

  local function coord_pair()
    local step = accept_kw("step")
    expect_op("(")
    local x = check_num(parse_expr())
    expect_op(",")
    local y = check_num(parse_expr())
    expect_op(")")
    return { step = step, x = x, y = y }
  end

  local function opt_expr()   -- an optional argument: nil when empty
    if is_op(",") or at_end() then return nil end
    return check_num(parse_expr())
  end

  local function parse_params(proc)
    local params = {}
    if accept_op("(") then
      if not accept_op(")") then
        repeat
          local t = nexttok()
          if t.t ~= "id" then err() end
          -- a module CONST is visible in every procedure: a parameter may not reuse its name
          if prog.consts[t.v] then err("Duplicate definition") end
          local p = { name = t.v, text = t.text, sfx = t.sfx }
          if accept_op("(") then expect_op(")"); p.array = true end
          if accept_kw("as") then
            local ty = nexttok()
            if ty.t ~= "kw" or not AS_TYPES[ty.v] then
              if ty.t == "id" then unsupported("user-defined TYPE", lineno) end
              err()
            end
            if t.sfx then err() end
            p.as = AS_TYPES[ty.v]
            if p.array then scope.as_array[t.v] = p.as else scope.as_scalar[t.v] = p.as end
          end
          p.ty = p.as or (t.sfx and TYPE_OF_SUFFIX[t.sfx]) or deftype[t.v:sub(1, 1)]
          params[#params + 1] = p
          if p.array then scope.arrays[t.v] = true end
        until not accept_op(",")
        expect_op(")")
      end
    end
    proc.params = params
    return params
  end

  local function begin_proc(kind, t)
    if cur_proc then err(kind == "deffn" and "Illegal in procedure" or "SUB/FUNCTION inside a procedure") end
    local proc = { kind = kind, name = t.v, text = t.text, line = lineno, body = {},
      ty = (kind ~= "sub") and fn_result_type(t) or nil }
    scope = { kind = kind, as_scalar = {}, as_array = {}, arrays = {}, shared = {} }
    if kind == "deffn" then
      -- DEF FN sees the module's variables: their AS types too
      setmetatable(scope.as_scalar, { __index = main_scope.as_scalar })
      setmetatable(scope.as_array, { __index = main_scope.as_array })
    end
    proc.scope = scope
    prog.procs[#prog.procs + 1] = proc
    add({ k = "procdef", proc = proc })
    return proc
  end

  local function end_proc(kind, line)
    if not cur_proc or cur_proc.kind ~= kind then
      err(kind == "sub" and "END SUB without SUB" or kind == "function"
        and "END FUNCTION without FUNCTION" or "END DEF without DEF")
    end
    cur_proc.end_line = line
    cur_proc = nil
    scope = main_scope
    body = prog.main
  end

  local function record_label(name)
    if prog.labels[name] then err("Duplicate label") end
    prog.labels[name] = { line = lineno, proc = cur_proc }
    prog.label_list[#prog.label_list + 1] = name
    add({ k = "label", name = name })
  end

  local GFX_UNSUPPORTED = {
    open = "OPEN", close = "CLOSE", write = "WRITE", lprint = "LPRINT", on = "ON",
    error = "ERROR", resume = "RESUME", chain = "CHAIN", common = "COMMON", type = "TYPE",
    static = "STATIC", erase = "ERASE", poke = "POKE", out = "OUT", wait = "WAIT", shell = "SHELL",
    kill = "KILL", name = "NAME", files = "FILES", chdir = "CHDIR", mkdir = "MKDIR",
    rmdir = "RMDIR", field = "FIELD", lset = "LSET", rset = "RSET", seek = "SEEK",
    clear = "CLEAR", run = "RUN", tron = "TRON", troff = "TROFF", bload = "BLOAD",
    bsave = "BSAVE", ioctl = "IOCTL", lock = "LOCK", unlock = "UNLOCK", reset = "RESET",
    timer = "TIMER ON/OFF", strig = "STRIG", pen = "PEN", com = "COM", signal = "SIGNAL",
    date = "DATE$", ["date$"] = "DATE$ statement", ["time$"] = "TIME$ statement",
    ["mid$"] = "MID$ statement", environ = "ENVIRON", setmem = "SETMEM", absolute = "CALL ABSOLUTE" }

  local function parse_print()
    local items = {}
    local last_sep = nil
    while not at_end() do
      if accept_op(";") then
        items[#items + 1] = { k = "sep", v = ";" }
        last_sep = ";"
      elseif accept_op(",") then
        items[#items + 1] = { k = "sep", v = "," }
        last_sep = ","
      elseif is_kw("tab") or is_kw("spc") then
        local which = nexttok().v
        expect_op("(")
        local e = check_num(parse_expr())
        expect_op(")")
        items[#items + 1] = { k = which, e = e }
        last_sep = nil
      elseif is_kw("using") then
        unsupported("PRINT USING", lineno)
      elseif is_op("#") then
        unsupported("PRINT #", lineno)
      else
        items[#items + 1] = { k = "expr", e = parse_expr() }
        last_sep = nil
      end
    end
    return { k = "print", items = items, newline = last_sep == nil }
  end

  local function parse_dim(redim)
    local shared = accept_kw("shared")
    if shared and cur_proc then err() end
    local decls = {}
    repeat
      local t = nexttok()
      if t.t ~= "id" then err() end
      local d = { name = t.v, text = t.text, sfx = t.sfx }
      if accept_op("(") then
        d.bounds = {}
        repeat
          local a = check_num(parse_expr())
          local lo, hi
          if accept_kw("to") then
            lo = a; hi = check_num(parse_expr())
          else
            hi = a
          end
          d.bounds[#d.bounds + 1] = { lo = lo, hi = hi }
        until not accept_op(",")
        expect_op(")")
      end
      if accept_kw("as") then
        local ty = nexttok()
        if ty.t ~= "kw" or not AS_TYPES[ty.v] then
          if ty.t == "id" then unsupported("user-defined TYPE", lineno) end
          err()
        end
        if t.sfx then err() end
        if ty.v == "string" and accept_op("*") then unsupported("fixed-length STRING", lineno) end
        d.as = AS_TYPES[ty.v]
        if d.bounds then scope.as_array[t.v] = d.as else scope.as_scalar[t.v] = d.as end
      end
      if d.bounds then
        d.ty = type_of_name(t, true)
        scope.arrays[t.v] = true
        if shared then prog.shared_arrays[t.v] = { as = d.as } end
      else
        d.ty = type_of_name(t, false)
        if shared then prog.shared[t.v] = { as = d.as } end
      end
      decls[#decls + 1] = d
    until not accept_op(",")
    return { k = "dim", decls = decls, shared = shared, redim = redim,
      base = prog.option_base }
  end

  -- a branch of a single-line IF: a line number (THEN 20 means GOTO 20) or statements
  local function parse_branch(stop_at_else)
    local body = {}
    if peek().t == "num" then
      body[1] = { k = "goto", label = label_name(nexttok()), line = lineno }
    else
      parse_stmt_list(body, stop_at_else)
    end
    return body
  end

  local function parse_if(stop_at_else)
    local cond = parse_expr()
    check_num(cond)
    local st = { k = "if1", cond = cond }
    if accept_kw("goto") then
      st.then_body = { { k = "goto", label = label_name(nexttok()), line = lineno } }
    else
      expect_kw("then")
      if peek().t == "eol" or is_kw("rem") then     -- only a comment after THEN: a block IF
        while peek().t ~= "eol" do pos = pos + 1 end
        return add({ k = "ifblock", cond = cond })
      end
      st.then_body = parse_branch(true)
    end
    if accept_kw("else") then st.else_body = parse_branch(stop_at_else) end
    return add(st)
  end

  local function parse_case()
    if accept_kw("else") then return add({ k = "case", is_else = true }) end
    local tests = {}
    repeat
      if accept_kw("is") then
        local t = nexttok()
        if t.t ~= "op" or not RELOPS[t.v] then err() end
        tests[#tests + 1] = { op = t.v, e = parse_add() }
      else
        local a = parse_expr()
        if accept_kw("to") then
          tests[#tests + 1] = { lo = a, hi = parse_expr() }
        else
          tests[#tests + 1] = { op = "=", e = a }
        end
      end
    until not accept_op(",")
    return add({ k = "case", tests = tests })
  end

  -- ---- the screen and the keyboard: each handler parses one statement kind -----------------
  -- A statement the runtime carries out as a call: {k = "rtcall", fn = helper, args = {exprs}}
  -- (nil for an argument left out).
  local function rtcall(fn, args)
    local n = 0
    for i in pairs(args or {}) do if i > n then n = i end end
    return add({ k = "rtcall", fn = fn, args = args or {}, nargs = n })
  end
  local function opt_any()   -- an optional argument of any type
    if is_op(",") or at_end() then return nil end
    return parse_expr()
  end
  local function arg_list(max)   -- a, , c: optional numeric arguments separated by commas
    local args = {}
    local i = 1
    args[i] = opt_expr()
    while accept_op(",") do
      i = i + 1
      if i > max then err() end
      args[i] = opt_expr()
    end
    return args, i
  end
  -- an array for GET/PUT: a name with an optional first element, a(), a(5), a(0, 1)
  local function block_array()
    local t = nexttok()
    if t.t ~= "id" then err() end
    local arr = { k = "arrayref", name = t.v, ty = type_of_name(t, true), text = t.text,
      proc = cur_proc }
    local idx = {}
    if accept_op("(") then
      if not accept_op(")") then
        idx = parse_args()
        for _, a in ipairs(idx) do check_num(a) end
      end
    end
    if arr.ty == "string" then err("Type mismatch") end
    scope.arrays[t.v] = true
    return arr, idx
  end
  local function input_targets()
    local targets = {}
    repeat targets[#targets + 1] = parse_lvalue() until not accept_op(",")
    return targets
  end
  local SCREEN_STMT = {}
  function SCREEN_STMT.locate()
    local args = arg_list(5)
    for i = 3, 5 do args[i] = nil end     -- the cursor's shape: nothing to draw
    return rtcall("locate", args)
  end
  function SCREEN_STMT.width()
    if is_op("#") or peek().t == "str" then unsupported("WIDTH of a device or file", lineno) end
    return rtcall("width", (arg_list(2)))
  end
  function SCREEN_STMT.draw() return rtcall("draw", { check_str(parse_expr()) }) end
  function SCREEN_STMT.pcopy()
    local a = check_num(parse_expr())
    expect_op(",")
    return rtcall("pcopy", { a, check_num(parse_expr()) })
  end
  function SCREEN_STMT.sleep()
    if at_end() then return rtcall("sleep", {}) end
    return rtcall("sleep", { check_num(parse_expr()) })
  end
  function SCREEN_STMT.beep() return rtcall("beep", {}) end
  function SCREEN_STMT.sound()
    local f = check_num(parse_expr())
    expect_op(",")
    return rtcall("sound", { f, check_num(parse_expr()) })
  end
  function SCREEN_STMT.play()
    if is_kw("on") or is_kw("off") or is_kw("stop") then unsupported("PLAY ON/OFF/STOP", lineno) end
    return rtcall("play", { check_str(parse_expr()) })
  end
  function SCREEN_STMT.key()
    -- KEY OFF/ON/LIST show or hide the function-key line: nothing on a picture
    if accept_kw("off") or accept_kw("on") or accept_kw("list") then return end
    if is_op("(") then unsupported("KEY(n) trapping", lineno) end
    local n = check_num(parse_expr())
    expect_op(",")
    return rtcall("key_def", { n, check_str(parse_expr()) })
  end
  function SCREEN_STMT.get()
    if is_op("#") or peek().t == "num" then unsupported("GET # (files)", lineno) end
    local p1 = coord_pair()
    expect_op("-")
    local p2 = coord_pair()
    expect_op(",")
    local arr, idx = block_array()
    return add({ k = "getput", get = true, p1 = p1, p2 = p2, array = arr, index = idx })
  end
  function SCREEN_STMT.put()
    if is_op("#") or peek().t == "num" then unsupported("PUT # (files)", lineno) end
    local p = coord_pair()
    expect_op(",")
    local arr, idx = block_array()
    local action = "xor"
    if accept_op(",") then
      local a = nexttok()
      local ok = { pset = true, preset = true, ["and"] = true, ["or"] = true, xor = true }
      if a.t ~= "kw" or not ok[a.v] then err() end
      action = a.v
    end
    return add({ k = "getput", p1 = p, array = arr, index = idx, action = action })
  end
  function SCREEN_STMT.input()
    if is_op("#") then unsupported("INPUT # (files)", lineno) end
    local st = { k = "input", same_line = accept_op(";") }
    if peek().t == "str" then
      st.prompt = nexttok().v
      if accept_op(",") then st.mark = false else expect_op(";"); st.mark = true end
    else
      st.mark = true
    end
    st.targets = input_targets()
    return add(st)
  end
  function SCREEN_STMT.line_input()
    if is_op("#") then unsupported("LINE INPUT # (files)", lineno) end
    local st = { k = "input", line_input = true, same_line = accept_op(";") }
    if peek().t == "str" then
      st.prompt = nexttok().v
      if not accept_op(";") then expect_op(",") end
    end
    st.targets = { parse_lvalue() }
    if st.targets[1].ty ~= "string" then err("Type mismatch") end
    return add(st)
  end
  function SCREEN_STMT.view_print()
    if at_end() then return rtcall("view_print", {}) end
    local a = check_num(parse_expr())
    expect_kw("to")
    return rtcall("view_print", { a, check_num(parse_expr()) })
  end

  parse_statement = function(in_if)
    local t = peek()
    if t.t == "id" then
      -- assignment, or a SUB call without CALL
      if subs[t.v] and not is_op("=", 1) then
        pos = pos + 1
        local args = {}
        if not at_end() then
          repeat args[#args + 1] = parse_expr() until not accept_op(",")
        end
        return add({ k = "call", name = t.v, args = args, text = t.text })
      end
      local target = parse_lvalue()
      if not accept_op("=") then
        if target.k == "var" and at_end() then
          err("Syntax error")   -- a bare name: QBasic would look for a SUB of that name
        end
        err()
      end
      local e = parse_expr()
      if (target.ty == "string") ~= (e.ty == "string") then err("Type mismatch") end
      return add({ k = "let", target = target, expr = e })
    end
    if t.t ~= "kw" then err() end
    pos = pos + 1
    local w = t.v
    if w == "line" and accept_kw("input") then return SCREEN_STMT.line_input() end
    if w == "view" and accept_kw("print") then return SCREEN_STMT.view_print() end
    if SCREEN_STMT[w] then return SCREEN_STMT[w]() end
    if w == "let" then
      local target = parse_lvalue()
      expect_op("=")
      local e = parse_expr()
      if (target.ty == "string") ~= (e.ty == "string") then err("Type mismatch") end
      return add({ k = "let", target = target, expr = e })
    elseif w == "rem" then
      return
    elseif w == "print" then
      return add(parse_print())
    elseif w == "screen" then
      local args = arg_list(4)
      -- a mode given as a number is checked before the program runs
      local m = args[1] and args[1].k == "num" and args[1].v
      if m and (m == 3 or m == 4 or m == 8 or m == 10 or m == 11) then
        err("SCREEN " .. m .. ": not supported by pointcalc (SCREEN 1, 2, 7, 9, 12 and 13 are)")
      end
      return rtcall("screen", args)
    elseif w == "cls" then
      local a = nil
      if not at_end() then a = check_num(parse_expr()) end
      return add({ k = "cls", arg = a })
    elseif w == "color" then
      local fg = opt_expr()
      local bg
      if accept_op(",") then bg = opt_expr() end
      if accept_op(",") then unsupported("COLOR with a border colour", lineno) end
      return add({ k = "color", fg = fg, bg = bg })
    elseif w == "palette" then
      if is_kw("using") then unsupported("PALETTE USING", lineno) end
      if at_end() then return add({ k = "palette" }) end
      local a = check_num(parse_expr())
      expect_op(",")
      local c = check_num(parse_expr())
      return add({ k = "palette", attr = a, color = c })
    elseif w == "pset" or w == "preset" then
      local p = coord_pair()
      local c
      if accept_op(",") then c = check_num(parse_expr()) end
      return add({ k = w, p = p, color = c })
    elseif w == "line" then
      local p1
      if not is_op("-") then p1 = coord_pair() end
      expect_op("-")
      local p2 = coord_pair()
      local c, style, pattern
      if accept_op(",") then
        c = opt_expr()
        if accept_op(",") then
          local s = nexttok()
          if not (s.t == "op" and s.v == ",") then
            if s.t ~= "id" or (s.v ~= "b" and s.v ~= "bf") or s.sfx then err() end
            style = s.v
          else
            pos = pos - 1
          end
          if accept_op(",") then
            if style == "bf" then err() end
            pattern = check_num(parse_expr())
          end
        end
      end
      return add({ k = "line", p1 = p1, p2 = p2, color = c, style = style, pattern = pattern })
    elseif w == "circle" then
      local p = coord_pair()
      expect_op(",")
      local r = check_num(parse_expr())
      local c, a0, a1, asp
      if accept_op(",") then
        c = opt_expr()
        if accept_op(",") then
          a0 = opt_expr()
          if accept_op(",") then
            a1 = opt_expr()
            if accept_op(",") then
              asp = opt_expr()
              if not asp then err() end
            end
          end
        end
      end
      return add({ k = "circle", p = p, r = r, color = c, a0 = a0, a1 = a1, aspect = asp })
    elseif w == "paint" then
      local p = coord_pair()
      local c, b
      if accept_op(",") then
        if not is_op(",") and not at_end() then
          c = parse_expr()
          if c.ty == "string" then unsupported("PAINT with a tile pattern", lineno) end
        end
        if accept_op(",") then
          b = opt_expr()
          if accept_op(",") then unsupported("PAINT with a background pattern", lineno) end
        end
      end
      return add({ k = "paint", p = p, color = c, border = b })
    elseif w == "window" or w == "view" then
      local screen = accept_kw("screen")
      if at_end() then
        if screen then err() end
        return add({ k = w })
      end
      local p1 = coord_pair()
      expect_op("-")
      local p2 = coord_pair()
      if p1.step or p2.step then err() end
      local st = { k = w, screen = screen, p1 = p1, p2 = p2 }
      if w == "view" and accept_op(",") then
        st.fill = opt_expr()
        if accept_op(",") then st.border = opt_expr() end
      end
      return add(st)
    elseif w == "dim" or w == "redim" then
      if w == "redim" and is_kw("preserve") then unsupported("REDIM PRESERVE", lineno) end
      return add(parse_dim(w == "redim"))
    elseif w == "const" then
      local decls = {}
      repeat
        local n = nexttok()
        if n.t ~= "id" then err() end
        expect_op("=")
        local e = parse_expr()
        local ty = n.sfx and TYPE_OF_SUFFIX[n.sfx] or e.ty
        if (ty == "string") ~= (e.ty == "string") then err("Type mismatch") end
        if prog.consts[n.v] then err("Duplicate definition") end
        local c = { name = n.v, ty = ty, text = n.text, line = lineno }
        decls[#decls + 1] = { const = c, expr = e }
        prog.consts[n.v] = c
      until not accept_op(",")
      return add({ k = "const", decls = decls })
    elseif w == "data" then
      local d = nexttok()
      if cur_proc then err("Illegal in procedure") end
      for _, item in ipairs(d.items) do
        prog.data[#prog.data + 1] = { text = item.text, quoted = item.quoted, line = lineno }
      end
      return add({ k = "data" })
    elseif w == "read" then
      local targets = {}
      repeat targets[#targets + 1] = parse_lvalue() until not accept_op(",")
      return add({ k = "read", targets = targets })
    elseif w == "restore" then
      local lbl
      if not at_end() then lbl = label_name(nexttok()) end
      return add({ k = "restore", label = lbl })
    elseif w == "for" then
      local v = parse_lvalue()
      if v.k ~= "var" or v.ty == "string" then err() end
      expect_op("=")
      local a = check_num(parse_expr())
      expect_kw("to")
      local b = check_num(parse_expr())
      local s
      if accept_kw("step") then s = check_num(parse_expr()) end
      return add({ k = "for", var = v, from = a, to = b, step = s })
    elseif w == "next" then
      if at_end() then return add({ k = "next" }) end
      repeat
        local v = parse_lvalue()
        if v.k ~= "var" then err() end
        add({ k = "next", var = v })
      until not accept_op(",")
      return
    elseif w == "if" then
      return parse_if(in_if)
    elseif w == "elseif" then
      local cond = check_num(parse_expr())
      expect_kw("then")
      if peek().t ~= "eol" then err() end
      return add({ k = "elseif", cond = cond })
    elseif w == "else" then
      return add({ k = "else" })
    elseif w == "end" then
      if at_end() then return add({ k = "end" }) end
      local what = nexttok()
      if what.t ~= "kw" then err() end
      if what.v == "if" then return add({ k = "endif" })
      elseif what.v == "select" then return add({ k = "endselect" })
      elseif what.v == "sub" then add({ k = "endsub" }); end_proc("sub", lineno); return
      elseif what.v == "function" then add({ k = "endfunction" }); end_proc("function", lineno); return
      elseif what.v == "def" then add({ k = "enddef" }); end_proc("deffn", lineno); return
      elseif what.v == "type" then unsupported("TYPE", lineno) end
      err()
    elseif w == "stop" or w == "system" then
      return add({ k = "end" })
    elseif w == "while" then
      return add({ k = "while", cond = check_num(parse_expr()) })
    elseif w == "wend" then
      return add({ k = "wend" })
    elseif w == "do" then
      local c
      if accept_kw("while") then c = { kind = "while", e = check_num(parse_expr()) }
      elseif accept_kw("until") then c = { kind = "until", e = check_num(parse_expr()) } end
      return add({ k = "do", cond = c })
    elseif w == "loop" then
      local c
      if accept_kw("while") then c = { kind = "while", e = check_num(parse_expr()) }
      elseif accept_kw("until") then c = { kind = "until", e = check_num(parse_expr()) } end
      return add({ k = "loop", cond = c })
    elseif w == "exit" then
      local what = nexttok()
      if what.t ~= "kw" then err() end
      local kinds = { ["for"] = "for", ["do"] = "do", sub = "sub", ["function"] = "function",
        def = "deffn" }
      if not kinds[what.v] then err() end
      return add({ k = "exit", what = kinds[what.v] })
    elseif w == "select" then
      expect_kw("case")
      return add({ k = "select", expr = parse_expr() })
    elseif w == "case" then
      return parse_case()
    elseif w == "goto" then
      return add({ k = "goto", label = label_name(nexttok()) })
    elseif w == "gosub" then
      return add({ k = "gosub", label = label_name(nexttok()) })
    elseif w == "return" then
      if not at_end() then unsupported("RETURN with a line number", lineno) end
      return add({ k = "return" })
    elseif w == "on" then
      if is_kw("error") or is_kw("key") or is_kw("timer") or is_kw("pen") or is_kw("play")
          or is_kw("strig") or is_kw("com") then
        unsupported("ON " .. peek().v:upper(), lineno)
      end
      local e = check_num(parse_expr())
      local gosub
      if accept_kw("goto") then gosub = false
      elseif accept_kw("gosub") then gosub = true
      else err() end
      local labels = {}
      repeat labels[#labels + 1] = label_name(nexttok()) until not accept_op(",")
      return add({ k = "on", expr = e, labels = labels, gosub = gosub })
    elseif w == "sub" then
      local n = nexttok()
      if n.t ~= "id" or n.sfx then err() end
      local proc = begin_proc("sub", n)
      parse_params(proc)
      if accept_kw("static") then unsupported("STATIC procedures", lineno) end
      cur_proc = proc
      body = proc.body
      return
    elseif w == "function" then
      local n = nexttok()
      if n.t ~= "id" then err() end
      local proc = begin_proc("function", n)
      parse_params(proc)
      if accept_kw("static") then unsupported("STATIC procedures", lineno) end
      cur_proc = proc
      body = proc.body
      return
    elseif w == "def" then
      local n = nexttok()
      if n.t == "kw" and n.v == "seg" then unsupported("DEF SEG", lineno) end
      if n.t ~= "id" or n.v:sub(1, 2) ~= "fn" then err() end
      local proc = begin_proc("deffn", n)
      parse_params(proc)
      for _, p in ipairs(proc.params) do if p.array then err() end end
      if accept_op("=") then
        cur_proc = proc
        local e = parse_expr()
        if (proc.ty == "string") ~= (e.ty == "string") then err("Type mismatch") end
        proc.expr = e
        proc.end_line = lineno
        cur_proc = nil
        scope = main_scope
        return
      end
      cur_proc = proc
      body = proc.body
      return
    elseif w == "declare" then
      local kind = nexttok()
      if kind.t ~= "kw" or (kind.v ~= "sub" and kind.v ~= "function") then err() end
      -- the declaration only announces the procedure: skip to the end of the statement
      while not at_end() do pos = pos + 1 end
      return
    elseif w == "call" then
      local n = nexttok()
      if n.t == "kw" and n.v == "absolute" then unsupported("CALL ABSOLUTE", lineno) end
      if n.t ~= "id" then err() end
      local args = {}
      if accept_op("(") then args = parse_args() end
      return add({ k = "call", name = n.v, args = args, text = n.text })
    elseif w == "shared" then
      if not cur_proc then err() end
      repeat
        local n = nexttok()
        if n.t ~= "id" then err() end
        local arr = false
        if accept_op("(") then expect_op(")"); arr = true end
        local as
        if accept_kw("as") then
          local ty = nexttok()
          if ty.t ~= "kw" or not AS_TYPES[ty.v] then err() end
          as = AS_TYPES[ty.v]
          if arr then scope.as_array[n.v] = as else scope.as_scalar[n.v] = as end
        end
        scope.shared[(arr and "()" or "") .. n.v] = true
        if arr then scope.arrays[n.v] = true end
      until not accept_op(",")
      return
    elseif w == "randomize" then
      if at_end() then return rtcall("randomize_ask", {}) end
      return add({ k = "randomize", expr = check_num(parse_expr()) })
    elseif w == "swap" then
      local a = parse_lvalue()
      expect_op(",")
      local b = parse_lvalue()
      if a.ty ~= b.ty then err("Type mismatch") end
      return add({ k = "swap", a = a, b = b })
    elseif w == "defint" or w == "deflng" or w == "defsng" or w == "defdbl" or w == "defstr" then
      local ty = ({ defint = "int", deflng = "long", defsng = "single", defdbl = "double",
        defstr = "string" })[w]
      repeat
        local a = nexttok()
        if a.t ~= "id" or #a.v ~= 1 or a.sfx then err() end
        local b = a
        if accept_op("-") then
          b = nexttok()
          if b.t ~= "id" or #b.v ~= 1 or b.sfx then err() end
        end
        for c = a.v:byte(), b.v:byte() do deftype[string.char(c)] = ty end
      until not accept_op(",")
      return
    elseif w == "option" then
      expect_kw("base")
      local n = nexttok()
      if n.t ~= "num" or (n.v ~= 0 and n.v ~= 1) then err() end
      prog.option_base = n.v
      return
    elseif w == "then" or w == "to" or w == "step" then
      err()
    end
    if GFX_UNSUPPORTED[w] then unsupported(GFX_UNSUPPORTED[w], lineno) end
    if FUNCS[w] then err() end
    unsupported(w:upper(), lineno)
  end

  -- ---- lines --------------------------------------------------------------------------------
  for i = 1, #lines do
    lineno = i
    toks, pos = all_toks[i], 1
    local t = peek()
    if t.t == "num" then
      pos = pos + 1
      record_label(label_name(t))
    elseif t.t == "id" and not t.sfx and is_op(":", 1) and not subs[t.v] then
      pos = pos + 2
      record_label(t.v)
    end
    parse_stmt_list(nil, false)
  end
  if cur_proc then
    err(cur_proc.kind == "sub" and "SUB without END SUB" or cur_proc.kind == "function"
      and "FUNCTION without END FUNCTION" or "DEF without END DEF", cur_proc.line)
  end

  -- labels of DATA: RESTORE label goes to the first DATA item at or after the label's line
  for name, l in pairs(prog.labels) do
    local idx = #prog.data + 1
    for j, d in ipairs(prog.data) do
      if d.line >= l.line then idx = j; break end
    end
    prog.data_labels[name] = idx
  end
  prog.main_scope = main_scope
  return prog
end

return M
