-- QBasic front end, pass 1: the parser.  Source lines -> a syntax tree, without types (the
-- resolve pass gives them) and without Lua names (the scope pass).
--
-- parse(source) returns a program:
--   lines      the physical source lines
--   main       the module's statements as a tree (qbasic_blocks.lua), with {k="procdef"} at
--              the place of each SUB, FUNCTION and DEF FN
--   procs      list of procedures {kind="sub"|"function"|"deffn", name, sfx, params, tree}
--              (a one-line DEF FN has expr instead of a tree)
--   functions, subs   name -> token: the FUNCTIONs and SUBs of the program (a FUNCTION's name
--              followed by "(" is a call, not an array)
--   data       DATA items in order {text, quoted, line}; data_labels: label -> first item
--   labels     label -> {line, proc}
-- Every statement has .line (its physical line); each statement kind has a short parsing
-- function in STMT below.  Errors are raised as {qb=true, msg, line}.
local lex = require "qbasic_lex"
local K = require "qbasic_keywords"
local expr_parser = require "qbasic_parse_expr"
local blocks = require "qbasic_blocks"

local M = {}

local function split_lines(source)
  local lines = {}
  source = source:gsub("^\239\187\191", "")     -- a UTF-8 byte-order mark
  for l in (source .. "\n"):gmatch("([^\n]*)\n") do
    lines[#lines + 1] = l:gsub("\r", "")
  end
  if source:sub(-1) == "\n" then lines[#lines] = nil end
  if #lines == 0 then lines[1] = "" end
  return lines
end

-- lex every line, and find the FUNCTIONs and SUBs (a FUNCTION's name decides call or array)
local function lex_all(prog)
  local all_toks, functions, subs = {}, {}, {}
  for i, l in ipairs(prog.lines) do
    local ok, t = pcall(lex.line, l)
    if not ok then
      if type(t) == "table" and t.qb then t.line = i end
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
  return all_toks
end

function M.parse(source)
  local prog = { lines = split_lines(source), main = {}, procs = {}, data = {},
    data_labels = {}, labels = {}, label_list = {}, option_base = 0, types = {} }
  local all_toks = lex_all(prog)
  local P = expr_parser.cursor(prog)
  local err, expr, opt_expr = P.err, P.expr, P.opt_expr
  local accept_op, accept_kw, expect_op, expect_kw = P.accept_op, P.accept_kw, P.expect_op,
    P.expect_kw
  local is_op, is_kw, at_end, peek, nexttok = P.is_op, P.is_kw, P.at_end, P.peek, P.next
  local body = prog.main               -- where statements go

  local function add(st)
    st.line = st.line or P.lineno
    body[#body + 1] = st
    return st
  end

  -- A statement the runtime carries out as a call: {k = "rtcall", fn = helper, args = {exprs}}
  -- (nil for an argument left out); K.RT_STATEMENTS gives the argument types
  local function rtcall(fn, args)
    local n = 0
    for i in pairs(args or {}) do if i > n then n = i end end
    return add({ k = "rtcall", fn = fn, args = args or {}, nargs = n })
  end
  local function arg_list(max)   -- a, , c: optional arguments separated by commas
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
  -- after AS: INTEGER, LONG, SINGLE, DOUBLE, STRING [* n], or a TYPE declared above;
  -- returns the type ("rec:name" for a TYPE) and the length of a fixed-length string
  local function as_type(allow_fixed)
    local ty = nexttok()
    if ty.t == "id" and not ty.sfx then
      if not prog.types[ty.v] then err("Type not defined") end
      return "rec:" .. ty.v
    end
    if ty.t ~= "kw" or not K.AS_TYPES[ty.v] then err() end
    if ty.v == "string" and accept_op("*") then
      local n = nexttok()
      if n.t ~= "num" or n.v ~= math.floor(n.v) or n.v < 1 or n.v > K.MAX_STRING then
        if n.t == "id" then P.unsupported("fixed-length STRING with a CONST length") end
        err()
      end
      if not allow_fixed then err() end
      return "string", n.v
    end
    return K.AS_TYPES[ty.v]
  end

  -- ---- procedures ---------------------------------------------------------------------------
  local function parse_params(proc)
    local params = {}
    if accept_op("(") and not accept_op(")") then
      repeat
        local t = nexttok()
        if t.t ~= "id" then err() end
        local p = { name = t.v, text = t.text, sfx = t.sfx }
        if accept_op("(") then expect_op(")"); p.array = true end
        if accept_kw("as") then
          p.as = as_type()
          if t.sfx then err() end
        end
        params[#params + 1] = p
      until not accept_op(",")
      expect_op(")")
    end
    proc.params = params
  end
  local function begin_proc(kind, t)
    if P.cur_proc then
      err(kind == "deffn" and "Illegal in procedure" or "SUB/FUNCTION inside a procedure")
    end
    local proc = { kind = kind, name = t.v, text = t.text, sfx = t.sfx, line = P.lineno,
      body = {} }
    prog.procs[#prog.procs + 1] = proc
    add({ k = "procdef", proc = proc })
    parse_params(proc)
    return proc
  end
  local function enter(proc)
    P.cur_proc = proc
    body = proc.body
  end
  local function end_proc(kind)
    local cur = P.cur_proc
    if not cur or cur.kind ~= kind then
      err(kind == "sub" and "END SUB without SUB" or kind == "function"
        and "END FUNCTION without FUNCTION" or "END DEF without DEF")
    end
    cur.end_line = P.lineno
    P.cur_proc = nil
    body = prog.main
  end

  local function record_label(name)
    if prog.labels[name] then err("Duplicate label") end
    prog.labels[name] = { line = P.lineno, proc = P.cur_proc }
    prog.label_list[#prog.label_list + 1] = name
    add({ k = "label", name = name })
  end

  -- ---- statement lists and IF -------------------------------------------------------------
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
        P.pos = P.pos + 1
        add({ k = "else" })
      elseif t.t == "op" and t.v == ":" then
        P.pos = P.pos + 1
      else
        parse_statement(stop_at_else)
        local t2 = peek()
        if not (t2.t == "eol" or (t2.t == "op" and t2.v == ":") or (t2.t == "kw" and t2.v == "else"
            and stop_at_else)) then
          err()
        end
      end
    end
    if list then body = saved end
  end

  -- a branch of a single-line IF: a line number (THEN 20 means GOTO 20) or statements
  local function parse_branch(stop_at_else)
    local list = {}
    if peek().t == "num" then
      list[1] = { k = "goto", label = P.label_name(nexttok()), line = P.lineno }
    else
      parse_stmt_list(list, stop_at_else)
    end
    return list
  end

  local function parse_if(stop_at_else)
    local cond = expr()
    local st = { k = "if1", cond = cond }
    if accept_kw("goto") then
      st.then_body = { { k = "goto", label = P.label_name(nexttok()), line = P.lineno } }
    else
      expect_kw("then")
      if peek().t == "eol" or is_kw("rem") then     -- only a comment after THEN: a block IF
        while peek().t ~= "eol" do P.pos = P.pos + 1 end
        return add({ k = "ifblock", cond = cond })
      end
      st.then_body = parse_branch(true)
    end
    if accept_kw("else") then st.else_body = parse_branch(stop_at_else) end
    return add(st)
  end

  -- ---- the statements, one function each ------------------------------------------------
  local STMT = {}
  local function loop_cond()
    if accept_kw("while") then return { kind = "while", e = expr() } end
    if accept_kw("until") then return { kind = "until", e = expr() } end
  end

  function STMT.rem() end
  function STMT.let()
    local target = P.lvalue()
    expect_op("=")
    return add({ k = "let", target = target, expr = expr() })
  end
  function STMT.print()
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
        local e = expr()
        expect_op(")")
        items[#items + 1] = { k = which, e = e }
        last_sep = nil
      elseif is_kw("using") and #items == 0 then
        return STMT.print_using()
      elseif is_op("#") then
        P.unsupported("PRINT #")
      else
        items[#items + 1] = { k = "expr", e = expr() }
        last_sep = nil
      end
    end
    return add({ k = "print", items = items, newline = last_sep == nil })
  end
  -- PRINT USING fmt$; values: the values separated by ; or , (both only separate here)
  function STMT.print_using()
    P.pos = P.pos + 1
    local st = { k = "print_using", format = expr(), values = {}, newline = true }
    if not accept_op(";") then expect_op(",") end
    while not at_end() do
      st.values[#st.values + 1] = expr()
      st.newline = true
      if accept_op(";") or accept_op(",") then st.newline = false
      elseif not at_end() then err() end
    end
    return add(st)
  end
  function STMT.screen()
    local args = arg_list(4)
    -- a mode given as a number is checked before the program runs
    local m = args[1] and args[1].k == "num" and args[1].v
    if m and (m == 3 or m == 4 or m == 8 or m == 10 or m == 11) then
      err("SCREEN " .. m .. ": not supported by pointcalc (SCREEN 1, 2, 7, 9, 12 and 13 are)")
    end
    return rtcall("screen", args)
  end
  function STMT.cls()
    local a = nil
    if not at_end() then a = expr() end
    return add({ k = "cls", arg = a })
  end
  function STMT.color()
    local fg = opt_expr()
    local bg
    if accept_op(",") then bg = opt_expr() end
    if accept_op(",") then P.unsupported("COLOR with a border colour") end
    return add({ k = "color", fg = fg, bg = bg })
  end
  function STMT.palette()
    if is_kw("using") then P.unsupported("PALETTE USING") end
    if at_end() then return add({ k = "palette" }) end
    local a = expr()
    expect_op(",")
    return add({ k = "palette", attr = a, color = expr() })
  end
  local function pset_stmt(w)
    return function()
      local p = P.coord_pair()
      local c
      if accept_op(",") then c = expr() end
      return add({ k = w, p = p, color = c })
    end
  end
  STMT.pset, STMT.preset = pset_stmt("pset"), pset_stmt("preset")
  function STMT.line()
    if accept_kw("input") then return STMT.line_input() end
    local p1
    if not is_op("-") then p1 = P.coord_pair() end
    expect_op("-")
    local p2 = P.coord_pair()
    local c, style, pattern
    if accept_op(",") then
      c = opt_expr()
      if accept_op(",") then
        local s = nexttok()
        if not (s.t == "op" and s.v == ",") then
          if s.t ~= "id" or (s.v ~= "b" and s.v ~= "bf") or s.sfx then err() end
          style = s.v
        else
          P.pos = P.pos - 1
        end
        if accept_op(",") then
          if style == "bf" then err() end
          pattern = expr()
        end
      end
    end
    return add({ k = "line", p1 = p1, p2 = p2, color = c, style = style, pattern = pattern })
  end
  function STMT.circle()
    local p = P.coord_pair()
    expect_op(",")
    local st = { k = "circle", p = p, r = expr() }
    if accept_op(",") then
      st.color = opt_expr()
      if accept_op(",") then
        st.a0 = opt_expr()
        if accept_op(",") then
          st.a1 = opt_expr()
          if accept_op(",") then
            st.aspect = opt_expr()
            if not st.aspect then err() end
          end
        end
      end
    end
    return add(st)
  end
  function STMT.paint()
    local st = { k = "paint", p = P.coord_pair() }
    if accept_op(",") then
      if not is_op(",") and not at_end() then st.color = expr() end
      if accept_op(",") then
        st.border = opt_expr()
        if accept_op(",") then P.unsupported("PAINT with a background pattern") end
      end
    end
    return add(st)
  end
  local function window_view(w)
    return function()
      local screen = accept_kw("screen")
      if at_end() then
        if screen then err() end
        return add({ k = w })
      end
      local p1 = P.coord_pair()
      expect_op("-")
      local p2 = P.coord_pair()
      if p1.step or p2.step then err() end
      local st = { k = w, screen = screen, p1 = p1, p2 = p2 }
      if w == "view" and accept_op(",") then
        st.fill = opt_expr()
        if accept_op(",") then st.border = opt_expr() end
      end
      return add(st)
    end
  end
  STMT.window = window_view("window")
  local view_graphics = window_view("view")
  function STMT.view()
    if accept_kw("print") then return STMT.view_print() end
    return view_graphics()
  end

  -- DIM, REDIM and STATIC (kind "static": the variables of a procedure that keep their values)
  local function parse_dim(redim, kind)
    local shared = accept_kw("shared")
    if shared and P.cur_proc then err() end
    local decls = {}
    repeat
      local t = nexttok()
      if t.t ~= "id" then err() end
      local d = { name = t.v, text = t.text, sfx = t.sfx }
      if accept_op("(") then
        d.bounds = {}
        repeat
          local a = expr()
          if accept_kw("to") then
            d.bounds[#d.bounds + 1] = { lo = a, hi = expr() }
          else
            d.bounds[#d.bounds + 1] = { hi = a }
          end
        until not accept_op(",")
        expect_op(")")
      end
      if accept_kw("as") then
        d.as, d.fixed = as_type(true)
        if t.sfx then err() end
      end
      decls[#decls + 1] = d
    until not accept_op(",")
    return add({ k = kind or "dim", decls = decls, shared = shared, redim = redim,
      base = prog.option_base })
  end
  function STMT.dim() return parse_dim(false) end
  function STMT.redim()
    if is_kw("preserve") then P.unsupported("REDIM PRESERVE") end
    return parse_dim(true)
  end
  function STMT.const()
    local decls = {}
    repeat
      local n = nexttok()
      if n.t ~= "id" then err() end
      expect_op("=")
      decls[#decls + 1] = { tok = n, expr = expr() }
    until not accept_op(",")
    return add({ k = "const", decls = decls })
  end
  function STMT.data()
    local d = nexttok()
    if P.cur_proc then err("Illegal in procedure") end
    for _, item in ipairs(d.items) do
      prog.data[#prog.data + 1] = { text = item.text, quoted = item.quoted, line = P.lineno }
    end
    return add({ k = "data" })
  end
  function STMT.read()
    local targets = {}
    repeat targets[#targets + 1] = P.lvalue() until not accept_op(",")
    return add({ k = "read", targets = targets })
  end
  function STMT.restore()
    local lbl
    if not at_end() then lbl = P.label_name(nexttok()) end
    return add({ k = "restore", label = lbl })
  end
  STMT["for"] = function()
    local v = P.lvalue()
    if v.k ~= "var" then err() end
    expect_op("=")
    local a = expr()
    expect_kw("to")
    local b = expr()
    local s
    if accept_kw("step") then s = expr() end
    return add({ k = "for", var = v, from = a, to = b, step = s })
  end
  function STMT.next()
    if at_end() then return add({ k = "next" }) end
    repeat
      local v = P.lvalue()
      if v.k ~= "var" then err() end
      add({ k = "next", var = v })
    until not accept_op(",")
  end
  STMT["if"] = function(in_if) return parse_if(in_if) end
  STMT["elseif"] = function()
    local cond = expr()
    expect_kw("then")
    if peek().t ~= "eol" then err() end
    return add({ k = "elseif", cond = cond })
  end
  STMT["else"] = function() return add({ k = "else" }) end
  STMT["end"] = function()
    if at_end() then return add({ k = "end" }) end
    local what = nexttok()
    if what.t ~= "kw" then err() end
    if what.v == "if" then return add({ k = "endif" })
    elseif what.v == "select" then return add({ k = "endselect" })
    elseif what.v == "sub" then add({ k = "endsub" }); end_proc("sub"); return
    elseif what.v == "function" then add({ k = "endfunction" }); end_proc("function"); return
    elseif what.v == "def" then add({ k = "enddef" }); end_proc("deffn"); return
    elseif what.v == "type" then err("END TYPE without TYPE") end
    err()
  end
  function STMT.stop() return add({ k = "end" }) end
  STMT.system = STMT.stop
  STMT["while"] = function() return add({ k = "while", cond = expr() }) end
  function STMT.wend() return add({ k = "wend" }) end
  STMT["do"] = function() return add({ k = "do", cond = loop_cond() }) end
  function STMT.loop() return add({ k = "loop", cond = loop_cond() }) end
  function STMT.exit()
    local what = nexttok()
    if what.t ~= "kw" then err() end
    local kinds = { ["for"] = "for", ["do"] = "do", sub = "sub", ["function"] = "function",
      def = "deffn" }
    if not kinds[what.v] then err() end
    return add({ k = "exit", what = kinds[what.v] })
  end
  function STMT.select()
    expect_kw("case")
    return add({ k = "select", expr = expr() })
  end
  function STMT.case()
    if accept_kw("else") then return add({ k = "case", is_else = true }) end
    local tests = {}
    repeat
      if accept_kw("is") then
        local t = nexttok()
        if t.t ~= "op" or not expr_parser.RELOPS[t.v] then err() end
        tests[#tests + 1] = { op = t.v, e = P.additive() }
      else
        local a = expr()
        if accept_kw("to") then
          tests[#tests + 1] = { lo = a, hi = expr() }
        else
          tests[#tests + 1] = { op = "=", e = a }
        end
      end
    until not accept_op(",")
    return add({ k = "case", tests = tests })
  end
  STMT["goto"] = function() return add({ k = "goto", label = P.label_name(nexttok()) }) end
  function STMT.gosub() return add({ k = "gosub", label = P.label_name(nexttok()) }) end
  STMT["return"] = function()
    if not at_end() then P.unsupported("RETURN with a line number") end
    return add({ k = "return" })
  end
  function STMT.on()
    for _, w in ipairs({ "error", "key", "timer", "pen", "play", "strig", "com" }) do
      if is_kw(w) then P.unsupported("ON " .. w:upper()) end
    end
    local e = expr()
    local gosub
    if accept_kw("goto") then gosub = false
    elseif accept_kw("gosub") then gosub = true
    else err() end
    local labels = {}
    repeat labels[#labels + 1] = P.label_name(nexttok()) until not accept_op(",")
    return add({ k = "on", expr = e, labels = labels, gosub = gosub })
  end
  -- SUB name (...) STATIC: every variable of the procedure keeps its value between calls
  local function static_proc(proc)
    if accept_kw("static") then proc.static_all = true end
  end
  function STMT.sub()
    local n = nexttok()
    if n.t ~= "id" or n.sfx then err() end
    local proc = begin_proc("sub", n)
    static_proc(proc)
    enter(proc)
  end
  STMT["function"] = function()
    local n = nexttok()
    if n.t ~= "id" then err() end
    local proc = begin_proc("function", n)
    static_proc(proc)
    enter(proc)
  end
  function STMT.static()
    if not P.cur_proc then err("Illegal outside of SUB, FUNCTION or DEF FN") end
    return parse_dim(false, "static")
  end
  function STMT.erase()
    local arrays = {}
    repeat
      local t = nexttok()
      if t.t ~= "id" then err() end
      arrays[#arrays + 1] = P.name_node("arrayref", t, { whole = true })
    until not accept_op(",")
    return add({ k = "erase", arrays = arrays })
  end
  -- MID$(s$, start[, n]) = t$: characters of s$ replaced in place
  STMT["mid$"] = function()
    expect_op("(")
    local st = { k = "midset", target = P.lvalue() }
    expect_op(",")
    st.start = expr()
    if accept_op(",") then st.len = expr() end
    expect_op(")")
    expect_op("=")
    st.expr = expr()
    return add(st)
  end
  -- TYPE name ... END TYPE: the lines between are fields (qbasic_parse's line loop)
  function STMT.type()
    if P.cur_proc then err("Illegal in procedure") end
    local n = nexttok()
    if n.t ~= "id" or n.sfx then err() end
    if prog.types[n.v] then err("Duplicate definition") end
    P.in_type = { name = n.v, text = n.text, fields = {}, order = {}, line = P.lineno }
  end
  -- a line inside TYPE ... END TYPE: "name AS type", or END TYPE
  local function type_line()
    local def = P.in_type
    local t = peek()
    if t.t == "eol" then return end
    if t.t == "kw" and t.v == "end" and is_kw("type", 1) then
      P.pos = P.pos + 2
      if #def.order == 0 then err("Element not defined") end
      prog.types[def.name] = def
      P.in_type = nil
      return
    end
    local f = nexttok()
    if f.t == "kw" then err("Statement illegal in TYPE block") end
    if f.t ~= "id" or f.sfx or f.v:find(".", 1, true) then err() end
    if def.fields[f.v] then err("Duplicate definition") end
    expect_kw("as")
    local ty, fixed = as_type(true)
    def.fields[f.v] = { name = f.v, ty = ty, fixed = fixed }
    def.order[#def.order + 1] = f.v
  end
  function STMT.def()
    local n = nexttok()
    if n.t == "kw" and n.v == "seg" then P.unsupported("DEF SEG") end
    if n.t ~= "id" or n.v:sub(1, 2) ~= "fn" then err() end
    local proc = begin_proc("deffn", n)
    for _, p in ipairs(proc.params) do if p.array then err() end end
    if accept_op("=") then
      P.cur_proc = proc
      proc.expr = expr()
      proc.end_line = P.lineno
      P.cur_proc = nil
      return
    end
    enter(proc)
  end
  function STMT.declare()
    local kind = nexttok()
    if kind.t ~= "kw" or (kind.v ~= "sub" and kind.v ~= "function") then err() end
    -- the declaration only announces the procedure: skip to the end of the statement
    while not at_end() do P.pos = P.pos + 1 end
  end
  function STMT.call()
    local n = nexttok()
    if n.t == "kw" and n.v == "absolute" then P.unsupported("CALL ABSOLUTE") end
    if n.t ~= "id" then err() end
    local args = {}
    if accept_op("(") then args = P.args() end
    return add({ k = "call", name = n.v, args = args, text = n.text })
  end
  function STMT.shared()
    if not P.cur_proc then err() end
    local names = {}
    repeat
      local n = nexttok()
      if n.t ~= "id" then err() end
      local item = { name = n.v }
      if accept_op("(") then expect_op(")"); item.array = true end
      if accept_kw("as") then item.as = as_type() end
      names[#names + 1] = item
    until not accept_op(",")
    return add({ k = "shared", names = names })
  end
  function STMT.randomize()
    if at_end() then return rtcall("randomize_ask", {}) end
    return add({ k = "randomize", expr = expr() })
  end
  function STMT.swap()
    local a = P.lvalue()
    expect_op(",")
    return add({ k = "swap", a = a, b = P.lvalue() })
  end
  local DEFTYPES = { defint = "int", deflng = "long", defsng = "single", defdbl = "double",
    defstr = "string" }
  local function deftype_stmt(w)
    return function()
      local ranges = {}
      repeat
        local a = nexttok()
        if a.t ~= "id" or #a.v ~= 1 or a.sfx then err() end
        local b = a
        if accept_op("-") then
          b = nexttok()
          if b.t ~= "id" or #b.v ~= 1 or b.sfx then err() end
        end
        ranges[#ranges + 1] = { a.v, b.v }
      until not accept_op(",")
      return add({ k = "deftype", ty = DEFTYPES[w], ranges = ranges })
    end
  end
  for w in pairs(DEFTYPES) do STMT[w] = deftype_stmt(w) end
  function STMT.option()
    expect_kw("base")
    local n = nexttok()
    if n.t ~= "num" or (n.v ~= 0 and n.v ~= 1) then err() end
    prog.option_base = n.v
  end

  -- ---- the screen and the keyboard ------------------------------------------------------
  function STMT.locate()
    local args = arg_list(5)
    for i = 3, 5 do args[i] = nil end     -- the cursor's shape: nothing to draw
    return rtcall("locate", args)
  end
  function STMT.width()
    if is_op("#") or peek().t == "str" then P.unsupported("WIDTH of a device or file") end
    return rtcall("width", (arg_list(2)))
  end
  function STMT.draw() return rtcall("draw", { expr() }) end
  function STMT.pcopy()
    local a = expr()
    expect_op(",")
    return rtcall("pcopy", { a, expr() })
  end
  function STMT.sleep()
    if at_end() then return rtcall("sleep", {}) end
    return rtcall("sleep", { expr() })
  end
  function STMT.beep() return rtcall("beep", {}) end
  function STMT.sound()
    local f = expr()
    expect_op(",")
    return rtcall("sound", { f, expr() })
  end
  function STMT.play()
    if is_kw("on") or is_kw("off") or is_kw("stop") then P.unsupported("PLAY ON/OFF/STOP") end
    return rtcall("play", { expr() })
  end
  function STMT.key()
    -- KEY OFF/ON/LIST show or hide the function-key line: nothing on a picture
    if accept_kw("off") or accept_kw("on") or accept_kw("list") then return end
    if is_op("(") then P.unsupported("KEY(n) trapping") end
    local n = expr()
    expect_op(",")
    return rtcall("key_def", { n, expr() })
  end
  -- an array for GET/PUT: a name with an optional first element, a(), a(5), a(0, 1)
  local function block_array()
    local t = nexttok()
    if t.t ~= "id" then err() end
    local arr = P.name_node("arrayref", t)
    local idx = {}
    if accept_op("(") and not accept_op(")") then idx = P.args() end
    return arr, idx
  end
  function STMT.get()
    if is_op("#") or peek().t == "num" then P.unsupported("GET # (files)") end
    local p1 = P.coord_pair()
    expect_op("-")
    local p2 = P.coord_pair()
    expect_op(",")
    local arr, idx = block_array()
    return add({ k = "getput", get = true, p1 = p1, p2 = p2, array = arr, index = idx })
  end
  function STMT.put()
    if is_op("#") or peek().t == "num" then P.unsupported("PUT # (files)") end
    local p = P.coord_pair()
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
  local function input_targets()
    local targets = {}
    repeat targets[#targets + 1] = P.lvalue() until not accept_op(",")
    return targets
  end
  function STMT.input()
    if is_op("#") then P.unsupported("INPUT # (files)") end
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
  function STMT.line_input()
    if is_op("#") then P.unsupported("LINE INPUT # (files)") end
    local st = { k = "input", line_input = true, same_line = accept_op(";") }
    if peek().t == "str" then
      st.prompt = nexttok().v
      if not accept_op(";") then expect_op(",") end
    end
    st.targets = { P.lvalue() }
    return add(st)
  end
  function STMT.view_print()
    if at_end() then return rtcall("view_print", {}) end
    local a = expr()
    expect_kw("to")
    return rtcall("view_print", { a, expr() })
  end

  -- ---- one statement ------------------------------------------------------------------------
  parse_statement = function(in_if)
    local t = peek()
    if t.t == "id" then
      -- assignment, or a SUB call without CALL
      if prog.subs[t.v] and not is_op("=", 1) then
        P.pos = P.pos + 1
        local args = {}
        if not at_end() then
          repeat args[#args + 1] = expr() until not accept_op(",")
        end
        return add({ k = "call", name = t.v, args = args, text = t.text })
      end
      local target = P.lvalue()
      if not accept_op("=") then err() end
      return add({ k = "let", target = target, expr = expr() })
    end
    if t.t ~= "kw" then err() end
    P.pos = P.pos + 1
    local w = t.v
    if STMT[w] then return STMT[w](in_if) end
    if w == "then" or w == "to" or w == "step" then err() end
    if K.UNSUPPORTED_STMTS[w] then P.unsupported(K.UNSUPPORTED_STMTS[w]) end
    if K.FUNCS[w] then err() end
    P.unsupported(w:upper())
  end

  -- ---- lines --------------------------------------------------------------------------------
  for i = 1, #prog.lines do
    P.lineno = i
    P.toks, P.pos = all_toks[i], 1
    local t = peek()
    if P.in_type then
      type_line()
      if peek().t ~= "eol" then err() end
      goto next_line
    end
    if t.t == "num" then
      P.pos = P.pos + 1
      record_label(P.label_name(t))
    elseif t.t == "id" and not t.sfx and is_op(":", 1) and not prog.subs[t.v] then
      P.pos = P.pos + 2
      record_label(t.v)
    end
    parse_stmt_list(nil, false)
    ::next_line::
  end
  if P.in_type then err("TYPE without END TYPE", P.in_type.line) end
  local cur = P.cur_proc
  if cur then
    err(cur.kind == "sub" and "SUB without END SUB" or cur.kind == "function"
      and "FUNCTION without END FUNCTION" or "DEF without END DEF", cur.line)
  end

  -- labels of DATA: RESTORE label goes to the first DATA item at or after the label's line
  for name, l in pairs(prog.labels) do
    local idx = #prog.data + 1
    for j, d in ipairs(prog.data) do
      if d.line >= l.line then idx = j; break end
    end
    prog.data_labels[name] = idx
  end

  -- the tree: blocks nested (the closing END SUB/FUNCTION/DEF ends the flat body)
  prog.main = blocks.build(prog.main)
  for _, proc in ipairs(prog.procs) do
    if not proc.expr then
      local b = proc.body
      local last = b[#b]
      if last and (last.k == "endsub" or last.k == "endfunction" or last.k == "enddef") then
        b[#b] = nil
      end
      proc.tree = blocks.build(b)
    end
  end
  return prog
end

return M
