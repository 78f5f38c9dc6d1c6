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

-- GW-BASIC's direct-mode commands: a line of a numbered listing without a number that starts
-- with one of them was typed at the prompt (SAVE "PROG", A), not part of the program
local DIRECT = { save = true, load = true, list = true, llist = true, run = true, new = true,
  auto = true, renum = true, delete = true, edit = true, cont = true, merge = true }

local function split_lines(source)
  local lines = {}
  source = source:gsub("^\239\187\191", "")     -- a UTF-8 byte-order mark
  -- DOS files: QBasic and GW-BASIC stop reading at the end-of-file byte Ctrl-Z (0x1A); a line
  -- ends at CR LF, LF or a CR alone (old Macintosh and some GW-BASIC listings)
  source = source:match("^[^\26]*")
  if source:find("\r[^\n]") or source:sub(-1) == "\r" then
    source = source:gsub("\r\n", "\n"):gsub("\r", "\n")
  end
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
    for j = 1, #t do
      if t[j].t == "kw" and t[j].v == "select" then prog.has_select = true end
    end
    for j = 1, #t - 1 do
      local a, b = t[j], t[j + 1]
      if a.t == "kw" and (a.v == "function" or a.v == "sub") and b.t == "id"
          and (j == 1 or t[j - 1].t == "kw" and t[j - 1].v == "declare" or t[j - 1].t == "num") then
        if a.v == "function" then functions[b.v] = b else subs[b.v] = b end
      end
    end
  end
  prog.functions, prog.subs = functions, subs
  -- GW-BASIC has no SELECT CASE, so IS is no reserved word there: in a numbered listing
  -- without SELECT it is a variable (IS = 1)
  if prog.numbered and not prog.has_select then
    for _, t in ipairs(all_toks) do
      for j, tok in ipairs(t) do
        if tok.t == "kw" and tok.v == "is" then
          t[j] = { t = "id", v = "is", text = "is", col = tok.col }
        end
      end
    end
  end
  return all_toks
end

local function add(P, st)
  st.line = st.line or P.lineno
  P.body[#P.body + 1] = st
  return st
end

-- A statement the runtime carries out as a call: {k = "rtcall", fn = helper, args = {exprs}}
-- (nil for an argument left out); K.RT_STATEMENTS gives the argument types
local function rtcall(P, fn, args)
  local n = 0
  for i in pairs(args or {}) do if i > n then n = i end end
  return add(P, { k = "rtcall", fn = fn, args = args or {}, nargs = n })
end
local function arg_list(P, max)   -- a, , c: optional arguments separated by commas
  local args = {}
  local i = 1
  args[i] = P:opt_expr()
  while P:accept_op(",") do
    i = i + 1
    if i > max then P:err() end
    args[i] = P:opt_expr()
  end
  return args, i
end
-- after AS: INTEGER, LONG, SINGLE, DOUBLE, STRING [* n], or a TYPE declared above;
-- returns the type ("rec:name" for a TYPE) and the length of a fixed-length string
local function as_type(P, allow_fixed)
  local ty = P:next()
  if ty.t == "id" and not ty.sfx then
    if not P.prog.types[ty.v] then P:err("Type not defined") end
    return "rec:" .. ty.v
  end
  if ty.t ~= "kw" or not K.AS_TYPES[ty.v] then P:err() end
  if ty.v == "string" and P:accept_op("*") then
    local n = P:next()
    if n.t ~= "num" or n.v ~= math.floor(n.v) or n.v < 1 or n.v > K.MAX_STRING then
      if n.t == "id" then P:unsupported("fixed-length STRING with a CONST length") end
      P:err()
    end
    if not allow_fixed then P:err() end
    return "string", n.v
  end
  return K.AS_TYPES[ty.v]
end

-- ---- procedures ---------------------------------------------------------------------------
local function parse_params(P, proc)
  local params = {}
  if P:accept_op("(") and not P:accept_op(")") then
    repeat
      local t = P:next()
      if t.t ~= "id" then P:err() end
      local p = { name = t.v, text = t.text, sfx = t.sfx }
      if P:accept_op("(") then P:expect_op(")"); p.array = true end
      if P:accept_kw("as") then
        p.as = as_type(P)
        if t.sfx then P:err() end
      end
      params[#params + 1] = p
    until not P:accept_op(",")
    P:expect_op(")")
  end
  proc.params = params
end
local function begin_proc(P, kind, t)
  if P.cur_proc then
    P:err(kind == "deffn" and "Illegal in procedure" or "SUB/FUNCTION inside a procedure")
  end
  local proc = { kind = kind, name = t.v, text = t.text, sfx = t.sfx, line = P.lineno,
    body = {} }
  P.prog.procs[#P.prog.procs + 1] = proc
  add(P, { k = "procdef", proc = proc })
  parse_params(P, proc)
  return proc
end
local function enter(P, proc)
  P.cur_proc = proc
  P.body = proc.body
end
local function end_proc(P, kind)
  local cur = P.cur_proc
  if not cur or cur.kind ~= kind then
    P:err(kind == "sub" and "END SUB without SUB" or kind == "function"
      and "END FUNCTION without FUNCTION" or "END DEF without DEF")
  end
  cur.end_line = P.lineno
  P.cur_proc = nil
  P.body = P.prog.main
end

local function record_label(P, name)
  if P.prog.labels[name] then P:err("Duplicate label") end
  P.prog.labels[name] = { line = P.lineno, proc = P.cur_proc }
  P.prog.label_list[#P.prog.label_list + 1] = name
  add(P, { k = "label", name = name })
end

-- ---- statement lists and IF -------------------------------------------------------------
local parse_statement
local file_record

-- statements up to the end of the line, or up to ELSE (single-line IF)
local function parse_stmt_list(P, list, stop_at_else)
  -- list: where the statements go (a single-line IF branch), or nil for the current body
  -- (a SUB or FUNCTION line switches the current body)
  local saved = P.body
  if list then P.body = list end
  while true do
    local t = P:peek()
    if t.t == "eol" then break end
    if t.t == "kw" and t.v == "else" then
      if stop_at_else then break end
      -- ELSE of a block IF: a statement of its own, possibly followed by more on the line
      P.pos = P.pos + 1
      add(P, { k = "else" })
    elseif t.t == "op" and t.v == ":" then
      P.pos = P.pos + 1
    else
      parse_statement(P, stop_at_else)
      local t2 = P:peek()
      if not (t2.t == "eol" or (t2.t == "op" and t2.v == ":") or (t2.t == "kw" and t2.v == "else"
          and stop_at_else)) then
        P:err()
      end
    end
  end
  if list then P.body = saved end
end

-- a branch of a single-line IF: a line number (THEN 20 means GOTO 20) or statements
local function parse_branch(P, stop_at_else)
  local list = {}
  if P:peek().t == "num" then
    list[1] = { k = "goto", label = P:label_name(P:next()), line = P.lineno }
  else
    parse_stmt_list(P, list, stop_at_else)
  end
  return list
end

local function parse_if(P, stop_at_else)
  local cond = P:expr()
  local st = { k = "if1", cond = cond }
  if P:accept_kw("goto") then
    st.then_body = { { k = "goto", label = P:label_name(P:next()), line = P.lineno } }
  else
    P:expect_kw("then")
    if P:peek().t == "eol" or P:is_kw("rem") then     -- only a comment after THEN: a block IF
      while P:peek().t ~= "eol" do P.pos = P.pos + 1 end
      return add(P, { k = "ifblock", cond = cond })
    end
    st.then_body = parse_branch(P, true)
  end
  if P:accept_kw("else") then st.else_body = parse_branch(P, stop_at_else) end
  return add(P, st)
end

-- ---- the statements, one function each ------------------------------------------------
local STMT = {}
local function loop_cond(P)
  if P:accept_kw("while") then return { kind = "while", e = P:expr() } end
  if P:accept_kw("until") then return { kind = "until", e = P:expr() } end
end

function STMT.rem(P) end
function STMT.let(P)
  local target = P:lvalue()
  P:expect_op("=")
  return add(P, { k = "let", target = target, expr = P:expr() })
end
function STMT.print(P)
  local items = {}
  local last_sep = nil
  while not P:at_end() do
    if P:accept_op(";") then
      items[#items + 1] = { k = "sep", v = ";" }
      last_sep = ";"
    elseif P:accept_op(",") then
      items[#items + 1] = { k = "sep", v = "," }
      last_sep = ","
    elseif P:is_kw("tab") or P:is_kw("spc") then
      local which = P:next().v
      P:expect_op("(")
      local e = P:expr()
      P:expect_op(")")
      items[#items + 1] = { k = which, e = e }
      last_sep = nil
    elseif P:is_kw("using") and #items == 0 then
      return STMT.print_using(P)
    elseif P:is_op("#") then
      if #items > 0 then P:err() end
      return STMT.print_file(P)
    else
      items[#items + 1] = { k = "expr", e = P:expr() }
      last_sep = nil
    end
  end
  return add(P, { k = "print", items = items, newline = last_sep == nil })
end
-- PRINT USING fmt$; values: the values separated by ; or , (both only separate here)
function STMT.print_using(P)
  P.pos = P.pos + 1
  local st = { k = "print_using", format = P:expr(), values = {}, newline = true }
  if not P:accept_op(";") then P:expect_op(",") end
  while not P:at_end() do
    st.values[#st.values + 1] = P:expr()
    st.newline = true
    if P:accept_op(";") or P:accept_op(",") then st.newline = false
    elseif not P:at_end() then P:err() end
  end
  return add(P, st)
end
function STMT.screen(P)
  local args = arg_list(P, 4)
  -- a mode given as a number is checked before the program runs
  local m = args[1] and args[1].k == "num" and args[1].v
  if m and (m == 3 or m == 4 or m == 10) then
    P:err("SCREEN " .. m .. ": not supported by pointcalc (SCREEN 1, 2, 7, 8, 9, 11, 12 and 13 are)")
  end
  return rtcall(P, "screen", args)
end
function STMT.cls(P)
  local a = nil
  if not P:at_end() then a = P:expr() end
  return add(P, { k = "cls", arg = a })
end
function STMT.color(P)
  local fg = P:opt_expr()
  local bg
  if P:accept_op(",") then bg = P:opt_expr() end
  local border
  if P:accept_op(",") then border = P:expr() end
  return add(P, { k = "color", fg = fg, bg = bg, border = border })
end
function STMT.palette(P)
  if P:accept_kw("using") then   -- PALETTE USING a(i): the colours from the array's elements
    local t = P:next()
    if t.t ~= "id" then P:err() end
    local st = { k = "palette_using", array = P:name_node("arrayref", t), index = {} }
    if P:accept_op("(") and not P:accept_op(")") then st.index = P:args() end
    return add(P, st)
  end
  if P:at_end() then return add(P, { k = "palette" }) end
  local a = P:expr()
  P:expect_op(",")
  return add(P, { k = "palette", attr = a, color = P:expr() })
end
local function pset_stmt(w)
  return function(P)
    local p = P:coord_pair()
    local c
    if P:accept_op(",") then c = P:expr() end
    return add(P, { k = w, p = p, color = c })
  end
end
STMT.pset, STMT.preset = pset_stmt("pset"), pset_stmt("preset")
function STMT.line(P)
  if P:accept_kw("input") then return STMT.line_input(P) end
  local p1
  if not P:is_op("-") then p1 = P:coord_pair() end
  P:expect_op("-")
  local p2 = P:coord_pair()
  local c, style, pattern
  if P:accept_op(",") then
    c = P:opt_expr()
    if P:accept_op(",") then
      local s = P:next()
      if not (s.t == "op" and s.v == ",") then
        if s.t ~= "id" or (s.v ~= "b" and s.v ~= "bf") or s.sfx then P:err() end
        style = s.v
      else
        P.pos = P.pos - 1
      end
      if P:accept_op(",") then
        if style == "bf" then P:err() end
        pattern = P:expr()
      end
    end
  end
  return add(P, { k = "line", p1 = p1, p2 = p2, color = c, style = style, pattern = pattern })
end
function STMT.circle(P)
  local p = P:coord_pair()
  P:expect_op(",")
  local st = { k = "circle", p = p, r = P:expr() }
  if P:accept_op(",") then
    st.color = P:opt_expr()
    if P:accept_op(",") then
      st.a0 = P:opt_expr()
      if P:accept_op(",") then
        st.a1 = P:opt_expr()
        if P:accept_op(",") then
          st.aspect = P:opt_expr()
          if not st.aspect then P:err() end
        end
      end
    end
  end
  return add(P, st)
end
function STMT.paint(P)
  local st = { k = "paint", p = P:coord_pair() }
  if P:accept_op(",") then
    if not P:is_op(",") and not P:at_end() then st.color = P:expr() end
    if P:accept_op(",") then
      st.border = P:opt_expr()
      if P:accept_op(",") then P:unsupported("PAINT with a background pattern") end
    end
  end
  return add(P, st)
end
local function window_view(w)
  return function(P)
    local screen = P:accept_kw("screen")
    if P:at_end() then
      if screen then P:err() end
      return add(P, { k = w })
    end
    local p1 = P:coord_pair()
    P:expect_op("-")
    local p2 = P:coord_pair()
    if p1.step or p2.step then P:err() end
    local st = { k = w, screen = screen, p1 = p1, p2 = p2 }
    if w == "view" and P:accept_op(",") then
      st.fill = P:opt_expr()
      if P:accept_op(",") then st.border = P:opt_expr() end
    end
    return add(P, st)
  end
end
STMT.window = window_view("window")
local view_graphics = window_view("view")
function STMT.view(P)
  if P:accept_kw("print") then return STMT.view_print(P) end
  return view_graphics(P)
end

-- DIM, REDIM and STATIC (kind "static": the variables of a procedure that keep their values)
local function parse_dim(P, redim, kind)
  local shared = P:accept_kw("shared")
  if shared and P.cur_proc then P:err() end
  local decls = {}
  repeat
    local t = P:next()
    if t.t ~= "id" then P:err() end
    local d = { name = t.v, text = t.text, sfx = t.sfx }
    if P:accept_op("(") then
      d.bounds = {}
      repeat
        local a = P:expr()
        if P:accept_kw("to") then
          d.bounds[#d.bounds + 1] = { lo = a, hi = P:expr() }
        else
          d.bounds[#d.bounds + 1] = { hi = a }
        end
      until not P:accept_op(",")
      P:expect_op(")")
    end
    if P:accept_kw("as") then
      d.as, d.fixed = as_type(P, true)
      if t.sfx then P:err() end
    end
    decls[#decls + 1] = d
  until not P:accept_op(",")
  return add(P, { k = kind or "dim", decls = decls, shared = shared, redim = redim,
    base = P.prog.option_base })
end
function STMT.dim(P) return parse_dim(P, false) end
function STMT.redim(P)
  if P:is_kw("preserve") then P:unsupported("REDIM PRESERVE") end
  return parse_dim(P, true)
end
function STMT.const(P)
  local decls = {}
  repeat
    local n = P:next()
    if n.t ~= "id" then P:err() end
    P:expect_op("=")
    decls[#decls + 1] = { tok = n, expr = P:expr() }
  until not P:accept_op(",")
  return add(P, { k = "const", decls = decls })
end
function STMT.data(P)
  local d = P:next()
  if P.cur_proc then P:err("Illegal in procedure") end
  for _, item in ipairs(d.items) do
    P.prog.data[#P.prog.data + 1] = { text = item.text, quoted = item.quoted, line = P.lineno }
  end
  return add(P, { k = "data" })
end
function STMT.read(P)
  local targets = {}
  repeat targets[#targets + 1] = P:lvalue() until not P:accept_op(",")
  return add(P, { k = "read", targets = targets })
end
function STMT.restore(P)
  local lbl
  if not P:at_end() then lbl = P:label_name(P:next()) end
  return add(P, { k = "restore", label = lbl })
end
STMT["for"] = function(P)
  local v = P:lvalue()
  if v.k ~= "var" then P:err() end
  P:expect_op("=")
  local a = P:expr()
  P:expect_kw("to")
  local b = P:expr()
  local s
  if P:accept_kw("step") then s = P:expr() end
  return add(P, { k = "for", var = v, from = a, to = b, step = s })
end
function STMT.next(P)
  if P:at_end() then return add(P, { k = "next" }) end
  repeat
    local v = P:lvalue()
    if v.k ~= "var" then P:err() end
    add(P, { k = "next", var = v })
  until not P:accept_op(",")
end
STMT["if"] = function(P, in_if) return parse_if(P, in_if) end
STMT["elseif"] = function(P)
  local cond = P:expr()
  P:expect_kw("then")
  if P:peek().t ~= "eol" then P:err() end
  return add(P, { k = "elseif", cond = cond })
end
STMT["else"] = function(P) return add(P, { k = "else" }) end
STMT["end"] = function(P)
  if P:at_end() then return add(P, { k = "end" }) end
  local what = P:next()
  if what.t ~= "kw" then P:err() end
  if what.v == "if" then return add(P, { k = "endif" })
  elseif what.v == "select" then return add(P, { k = "endselect" })
  elseif what.v == "sub" then add(P, { k = "endsub" }); end_proc(P, "sub"); return
  elseif what.v == "function" then add(P, { k = "endfunction" }); end_proc(P, "function"); return
  elseif what.v == "def" then add(P, { k = "enddef" }); end_proc(P, "deffn"); return
  elseif what.v == "type" then P:err("END TYPE without TYPE") end
  P:err()
end
function STMT.stop(P) return add(P, { k = "end" }) end
STMT.system = STMT.stop
STMT["while"] = function(P) return add(P, { k = "while", cond = P:expr() }) end
function STMT.wend(P) return add(P, { k = "wend" }) end
STMT["do"] = function(P) return add(P, { k = "do", cond = loop_cond(P) }) end
function STMT.loop(P) return add(P, { k = "loop", cond = loop_cond(P) }) end
function STMT.exit(P)
  local what = P:next()
  if what.t ~= "kw" then P:err() end
  local kinds = { ["for"] = "for", ["do"] = "do", sub = "sub", ["function"] = "function",
    def = "deffn" }
  if not kinds[what.v] then P:err() end
  return add(P, { k = "exit", what = kinds[what.v] })
end
function STMT.select(P)
  P:expect_kw("case")
  return add(P, { k = "select", expr = P:expr() })
end
function STMT.case(P)
  if P:accept_kw("else") then return add(P, { k = "case", is_else = true }) end
  local tests = {}
  repeat
    if P:accept_kw("is") then
      local t = P:next()
      if t.t ~= "op" or not expr_parser.RELOPS[t.v] then P:err() end
      tests[#tests + 1] = { op = t.v, e = P:additive() }
    else
      local a = P:expr()
      if P:accept_kw("to") then
        tests[#tests + 1] = { lo = a, hi = P:expr() }
      else
        tests[#tests + 1] = { op = "=", e = a }
      end
    end
  until not P:accept_op(",")
  return add(P, { k = "case", tests = tests })
end
STMT["goto"] = function(P) return add(P, { k = "goto", label = P:label_name(P:next()) }) end
function STMT.gosub(P) return add(P, { k = "gosub", label = P:label_name(P:next()) }) end
-- RESUME [0 | NEXT | label]: back from the error handler
function STMT.resume(P)
  if P:at_end() then return add(P, { k = "resume", what = "retry" }) end
  if P:accept_kw("next") then return add(P, { k = "resume", what = "next" }) end
  local t = P:next()
  if t.t == "num" and t.v == 0 then return add(P, { k = "resume", what = "retry" }) end
  return add(P, { k = "resume", what = "label", label = P:label_name(t) })
end
function STMT.error(P) return rtcall(P, "error_n", { P:expr() }) end
-- RETURN [line]: with a line, back to that line instead of after the GOSUB (QBasic, GW-BASIC)
STMT["return"] = function(P)
  if P:at_end() then return add(P, { k = "return" }) end
  return add(P, { k = "return", label = P:label_name(P:next()) })
end
-- ON ERROR GOTO label | 0: the error handler (qbasic_control makes it a subroutine)
local function on_error(P)
  P:expect_kw("goto")
  local t = P:next()
  if t.t == "num" and t.v == 0 then return add(P, { k = "onerror" }) end
  return add(P, { k = "onerror", label = P:label_name(t) })
end
function STMT.on(P)
  if P:accept_kw("error") then return on_error(P) end
  for _, w in ipairs({ "key", "timer", "pen", "play", "strig", "com" }) do
    if P:is_kw(w) then P:unsupported("ON " .. w:upper()) end
  end
  local e = P:expr()
  local gosub
  if P:accept_kw("goto") then gosub = false
  elseif P:accept_kw("gosub") then gosub = true
  else P:err() end
  local labels = {}
  repeat labels[#labels + 1] = P:label_name(P:next()) until not P:accept_op(",")
  return add(P, { k = "on", expr = e, labels = labels, gosub = gosub })
end
-- SUB name (...) STATIC: every variable of the procedure keeps its value between calls
local function static_proc(P, proc)
  if P:accept_kw("static") then proc.static_all = true end
end
function STMT.sub(P)
  local n = P:next()
  if n.t ~= "id" or n.sfx then P:err() end
  local proc = begin_proc(P, "sub", n)
  static_proc(P, proc)
  enter(P, proc)
end
STMT["function"] = function(P)
  local n = P:next()
  if n.t ~= "id" then P:err() end
  local proc = begin_proc(P, "function", n)
  static_proc(P, proc)
  enter(P, proc)
end
function STMT.static(P)
  if not P.cur_proc then P:err("Illegal outside of SUB, FUNCTION or DEF FN") end
  return parse_dim(P, false, "static")
end
function STMT.erase(P)
  local arrays = {}
  repeat
    local t = P:next()
    if t.t ~= "id" then P:err() end
    arrays[#arrays + 1] = P:name_node("arrayref", t, { whole = true })
  until not P:accept_op(",")
  return add(P, { k = "erase", arrays = arrays })
end
-- MID$(s$, start[, n]) = t$: characters of s$ replaced in place
STMT["mid$"] = function(P)
  P:expect_op("(")
  local st = { k = "midset", target = P:lvalue() }
  P:expect_op(",")
  st.start = P:expr()
  if P:accept_op(",") then st.len = P:expr() end
  P:expect_op(")")
  P:expect_op("=")
  st.expr = P:expr()
  return add(P, st)
end
-- TYPE name ... END TYPE: the lines between are fields (qbasic_parse's line loop)
function STMT.type(P)
  if P.cur_proc then P:err("Illegal in procedure") end
  local n = P:next()
  if n.t ~= "id" or n.sfx then P:err() end
  if P.prog.types[n.v] then P:err("Duplicate definition") end
  P.in_type = { name = n.v, text = n.text, fields = {}, order = {}, line = P.lineno }
end
-- a line inside TYPE ... END TYPE: "name AS type", or END TYPE
local function type_line(P)
  local def = P.in_type
  local t = P:peek()
  if t.t == "eol" then return end
  if t.t == "kw" and t.v == "end" and P:is_kw("type", 1) then
    P.pos = P.pos + 2
    if #def.order == 0 then P:err("Element not defined") end
    P.prog.types[def.name] = def
    P.in_type = nil
    return
  end
  local f = P:next()
  if f.t == "kw" then P:err("Statement illegal in TYPE block") end
  if f.t ~= "id" or f.sfx or f.v:find(".", 1, true) then P:err() end
  if def.fields[f.v] then P:err("Duplicate definition") end
  P:expect_kw("as")
  local ty, fixed = as_type(P, true)
  def.fields[f.v] = { name = f.v, ty = ty, fixed = fixed }
  def.order[#def.order + 1] = f.v
end
function STMT.def(P)
  local n = P:next()
  if n.t == "kw" and n.v == "seg" then   -- DEF SEG [= segment]: PEEK and POKE's segment
    if not P:accept_op("=") then return rtcall(P, "def_seg", {}) end
    return rtcall(P, "def_seg", { P:expr() })
  end
  if n.t ~= "id" or n.v:sub(1, 2) ~= "fn" then P:err() end
  local proc = begin_proc(P, "deffn", n)
  for _, p in ipairs(proc.params) do if p.array then P:err() end end
  if P:accept_op("=") then
    P.cur_proc = proc
    proc.expr = P:expr()
    proc.end_line = P.lineno
    P.cur_proc = nil
    return
  end
  enter(P, proc)
end
function STMT.declare(P)
  local kind = P:next()
  if kind.t ~= "kw" or (kind.v ~= "sub" and kind.v ~= "function") then P:err() end
  -- the declaration only announces the procedure: skip to the end of the statement
  while not P:at_end() do P.pos = P.pos + 1 end
end
function STMT.call(P)
  local n = P:next()
  if n.t == "kw" and n.v == "absolute" then
    P:err("CALL ABSOLUTE: not supported by pointcalc (it runs x86 machine code from memory, and "
      .. "pointcalc emulates no processor)")
  end
  if n.t ~= "id" then P:err() end
  local args = {}
  if P:accept_op("(") then args = P:args() end
  return add(P, { k = "call", name = n.v, args = args, text = n.text })
end
function STMT.shared(P)
  if not P.cur_proc then P:err() end
  local names = {}
  repeat
    local n = P:next()
    if n.t ~= "id" then P:err() end
    local item = { name = n.v }
    if P:accept_op("(") then P:expect_op(")"); item.array = true end
    if P:accept_kw("as") then item.as = as_type(P) end
    names[#names + 1] = item
  until not P:accept_op(",")
  return add(P, { k = "shared", names = names })
end
-- COMMON [SHARED] [/block/] a, b$, c() [AS type]: the variables CHAIN passes on, by position
function STMT.common(P)
  if P.cur_proc then P:err("Illegal in procedure") end
  local shared = P:accept_kw("shared")
  if P:accept_op("/") then   -- a named block: QuickBASIC's, kept with the blank one
    P:next()
    P:expect_op("/")
  end
  local items = {}
  repeat
    local t = P:next()
    if t.t ~= "id" then P:err() end
    local item = { name = t.v, text = t.text, sfx = t.sfx }
    if P:accept_op("(") then
      -- QuickBASIC allows a number of dimensions here: it is not needed
      if not P:accept_op(")") then P:expr(); P:expect_op(")") end
      item.array = true
    end
    if P:accept_kw("as") then item.as = as_type(P) end
    item.node = P:name_node(item.array and "arrayref" or "var", t, { whole = item.array })
    items[#items + 1] = item
  until not P:accept_op(",")
  return add(P, { k = "common", items = items, shared = shared })
end
-- BSAVE f$, offset, length and BLOAD f$ [, offset]: memory (SCREEN 13's pixels) to a file
function STMT.bsave(P)
  local f = P:expr()
  P:expect_op(",")
  local off = P:expr()
  P:expect_op(",")
  return rtcall(P, "bsave", { f, off, P:expr() })
end
function STMT.bload(P)
  local f = P:expr()
  if P:accept_op(",") then return rtcall(P, "bload", { f, P:expr() }) end
  return rtcall(P, "bload", { f })
end
function STMT.chain(P) return rtcall(P, "chain", { P:expr() }) end
-- RUN: the program again from the start, its variables cleared; RUN f$: another program
function STMT.run(P)
  if P:at_end() then return rtcall(P, "run_program", {}) end
  if P:peek().t == "num" then P:unsupported("RUN with a line number") end
  return rtcall(P, "run_program", { P:expr() })
end
function STMT.randomize(P)
  if P:at_end() then return rtcall(P, "randomize_ask", {}) end
  return add(P, { k = "randomize", expr = P:expr() })
end
-- LSET a$ = b$, RSET a$ = b$: b$ left or right in a$'s length (padded with spaces, cut)
local function justify(P, right)
  local target = P:lvalue()
  P:expect_op("=")
  return add(P, { k = "justify", right = right, target = target, expr = P:expr() })
end
function STMT.lset(P) return justify(P, false) end
function STMT.rset(P) return justify(P, true) end
-- CLEAR [, [n] [, n]]: every variable of the module back to 0 and "" (the sizes are DOS's)
function STMT.clear(P)
  if P.cur_proc then P:err("Illegal in procedure") end
  while not P:at_end() do P.pos = P.pos + 1 end
  return add(P, { k = "clear" })
end
-- TIME$ = "hh:mm:ss", DATE$ = "mm-dd-yyyy": the virtual clock and calendar
STMT["time$"] = function(P) P:expect_op("="); return rtcall(P, "set_time", { P:expr() }) end
STMT["date$"] = function(P) P:expect_op("="); return rtcall(P, "set_date", { P:expr() }) end
function STMT.swap(P)
  local a = P:lvalue()
  P:expect_op(",")
  return add(P, { k = "swap", a = a, b = P:lvalue() })
end
local DEFTYPES = { defint = "int", deflng = "long", defsng = "single", defdbl = "double",
  defstr = "string" }
local function deftype_stmt(w)
  return function(P)
    local ranges = {}
    repeat
      local a = P:next()
      if a.t ~= "id" or #a.v ~= 1 or a.sfx then P:err() end
      local b = a
      if P:accept_op("-") then
        b = P:next()
        if b.t ~= "id" or #b.v ~= 1 or b.sfx then P:err() end
      end
      ranges[#ranges + 1] = { a.v, b.v }
    until not P:accept_op(",")
    return add(P, { k = "deftype", ty = DEFTYPES[w], ranges = ranges })
  end
end
for w in pairs(DEFTYPES) do STMT[w] = deftype_stmt(w) end
function STMT.option(P)
  P:expect_kw("base")
  local n = P:next()
  if n.t ~= "num" or (n.v ~= 0 and n.v ~= 1) then P:err() end
  P.prog.option_base = n.v
end

-- ---- the screen and the keyboard ------------------------------------------------------
function STMT.locate(P)
  local args = arg_list(P, 5)
  for i = 3, 5 do args[i] = nil end     -- the cursor's shape: nothing to draw
  return rtcall(P, "locate", args)
end
function STMT.width(P)
  if P:is_op("#") or P:peek().t == "str" then P:unsupported("WIDTH of a device or file") end
  return rtcall(P, "width", (arg_list(P, 2)))
end
function STMT.draw(P) return rtcall(P, "draw", { P:expr() }) end
function STMT.pcopy(P)
  local a = P:expr()
  P:expect_op(",")
  return rtcall(P, "pcopy", { a, P:expr() })
end
function STMT.sleep(P)
  if P:at_end() then return rtcall(P, "sleep", {}) end
  return rtcall(P, "sleep", { P:expr() })
end
function STMT.beep(P) return rtcall(P, "beep", {}) end
-- the emulated PC's ports and memory (qbasic_hw.lua)
local function two_args(P, fn)
  local a = P:expr()
  P:expect_op(",")
  return rtcall(P, fn, { a, P:expr() })
end
function STMT.out(P) return two_args(P, "out_port") end
function STMT.poke(P) return two_args(P, "poke") end
function STMT.wait(P)
  local a = P:expr()
  P:expect_op(",")
  local args = { a, P:expr() }
  if P:accept_op(",") then args[3] = P:expr() end
  return rtcall(P, "wait_port", args)
end
function STMT.sound(P)
  local f = P:expr()
  P:expect_op(",")
  return rtcall(P, "sound", { f, P:expr() })
end
function STMT.play(P)
  if P:is_kw("on") or P:is_kw("off") or P:is_kw("stop") then P:unsupported("PLAY ON/OFF/STOP") end
  return rtcall(P, "play", { P:expr() })
end
function STMT.key(P)
  -- KEY OFF/ON/LIST show or hide the function-key line: nothing on a picture
  if P:accept_kw("off") or P:accept_kw("on") or P:accept_kw("list") then return end
  if P:is_op("(") then P:unsupported("KEY(n) trapping") end
  local n = P:expr()
  P:expect_op(",")
  return rtcall(P, "key_def", { n, P:expr() })
end
-- ---- files (qbasic_files.lua) ------------------------------------------------------------
-- [#]n: a file number
local function file_number(P)
  P:accept_op("#")
  return P:expr()
end
-- OPEN f$ FOR mode AS [#]n [LEN = r], or GW-BASIC's OPEN mode$, [#]n, f$ [, r]
local OPEN_MODES = { input = "I", output = "O", append = "A", random = "R", binary = "B" }
function STMT.open(P)
  local first = P:expr()
  if P:accept_op(",") then
    local n = file_number(P)
    P:expect_op(",")
    local f = P:expr()
    local len
    if P:accept_op(",") then len = P:expr() end
    return rtcall(P, "open_file", { f, first, n, len })
  end
  local mode = { k = "str", v = "R", ty = "string" }
  if P:accept_kw("for") then
    local m = P:next()
    if m.t ~= "kw" or not OPEN_MODES[m.v] then P:err() end
    mode.v = OPEN_MODES[m.v]
  end
  -- ACCESS and LOCK clauses: one program at a time, nothing to share
  while not P:is_kw("as") and not P:at_end() do P.pos = P.pos + 1 end
  P:expect_kw("as")
  local n = file_number(P)
  local len
  if P:accept_kw("len") then
    P:expect_op("=")
    len = P:expr()
  end
  return rtcall(P, "open_file", { first, mode, n, len })
end
function STMT.close(P)
  local args = {}
  while not P:at_end() do
    args[#args + 1] = file_number(P)
    if not P:accept_op(",") then break end
  end
  return add(P, { k = "close", files = args })
end
-- PRINT #n, items and WRITE [#n,] values: after the file number, PRINT's items
function STMT.print_file(P)
  P.pos = P.pos + 1
  local file = P:expr()
  P:expect_op(",")
  local st
  if P:is_kw("using") then st = STMT.print_using(P) else st = STMT.print(P) end
  st.file = file
  return st
end
function STMT.write(P)
  local st = { k = "write", values = {} }
  if P:accept_op("#") then
    st.file = P:expr()
    if not P:accept_op(",") then return add(P, st) end
  end
  if not P:at_end() then
    repeat st.values[#st.values + 1] = P:expr() until not P:accept_op(",")
  end
  return add(P, st)
end
-- GET #n [, record] [, variable], PUT #n [, record] [, variable]
function file_record(P, which)
  local st = { k = "frecord", which = which, file = file_number(P) }
  if P:accept_op(",") then
    if not P:is_op(",") and not P:at_end() then st.record = P:expr() end
    if P:accept_op(",") then st.var = P:lvalue() end
  end
  return add(P, st)
end
-- FIELD #n, width AS v$, ...: the string variables that are the record's buffer
function STMT.field(P)
  local st = { k = "field", file = file_number(P), fields = {} }
  while P:accept_op(",") do
    local w = P:expr()
    P:expect_kw("as")
    st.fields[#st.fields + 1] = { width = w, var = P:lvalue() }
  end
  return add(P, st)
end
function STMT.seek(P)
  local n = file_number(P)
  P:expect_op(",")
  return rtcall(P, "seek_file", { n, P:expr() })
end
function STMT.kill(P) return rtcall(P, "kill_file", { P:expr() }) end
STMT["name"] = function(P)
  local a = P:expr()
  P:expect_kw("as")
  return rtcall(P, "name_file", { a, P:expr() })
end

-- an array for GET/PUT: a name with an optional first element, a(), a(5), a(0, 1)
local function block_array(P)
  local t = P:next()
  if t.t ~= "id" then P:err() end
  local arr = P:name_node("arrayref", t)
  local idx = {}
  if P:accept_op("(") and not P:accept_op(")") then idx = P:args() end
  return arr, idx
end
function STMT.get(P)
  if P:is_op("#") or P:peek().t == "num" then return file_record(P, "get") end
  local p1 = P:coord_pair()
  P:expect_op("-")
  local p2 = P:coord_pair()
  P:expect_op(",")
  local arr, idx = block_array(P)
  return add(P, { k = "getput", get = true, p1 = p1, p2 = p2, array = arr, index = idx })
end
function STMT.put(P)
  if P:is_op("#") or P:peek().t == "num" then return file_record(P, "put") end
  local p = P:coord_pair()
  P:expect_op(",")
  local arr, idx = block_array(P)
  local action = "xor"
  if P:accept_op(",") then
    local a = P:next()
    local ok = { pset = true, preset = true, ["and"] = true, ["or"] = true, xor = true }
    if a.t ~= "kw" or not ok[a.v] then P:err() end
    action = a.v
  end
  return add(P, { k = "getput", p1 = p, array = arr, index = idx, action = action })
end
local function input_targets(P)
  local targets = {}
  repeat targets[#targets + 1] = P:lvalue() until not P:accept_op(",")
  return targets
end
function STMT.input(P)
  if P:accept_op("#") then
    local st = { k = "finput", file = P:expr() }
    P:expect_op(",")
    st.targets = input_targets(P)
    return add(P, st)
  end
  local st = { k = "input", same_line = P:accept_op(";") }
  if P:peek().t == "str" then
    st.prompt = P:next().v
    if P:accept_op(",") then st.mark = false else P:expect_op(";"); st.mark = true end
  else
    st.mark = true
  end
  st.targets = input_targets(P)
  return add(P, st)
end
function STMT.line_input(P)
  if P:accept_op("#") then
    local st = { k = "finput", line_input = true, file = P:expr() }
    P:expect_op(",")
    st.targets = { P:lvalue() }
    return add(P, st)
  end
  local st = { k = "input", line_input = true, same_line = P:accept_op(";") }
  if P:peek().t == "str" then
    st.prompt = P:next().v
    if not P:accept_op(";") then P:expect_op(",") end
  end
  st.targets = { P:lvalue() }
  return add(P, st)
end
function STMT.view_print(P)
  if P:at_end() then return rtcall(P, "view_print", {}) end
  local a = P:expr()
  P:expect_kw("to")
  return rtcall(P, "view_print", { a, P:expr() })
end

-- ---- one statement ------------------------------------------------------------------------
-- reserved words that begin no statement: QBasic's Syntax error (not "not supported")
local NOT_STATEMENTS = {}
for w in ([[then to step base is as access alias any append binary byval cdecl double integer
  long single string output random preserve seg using until xor and or not mod eqv imp
  off]]):gmatch("%S+") do NOT_STATEMENTS[w] = true end
parse_statement = function(P, in_if)
  local t = P:peek()
  if (t.t == "id" or t.t == "kw" and t.v == "list") and DIRECT[t.v] and not P.prog.subs[t.v]
      and not P:is_op("=", 1) and not P:is_op("(", 1) then
    P:err("Syntax error (" .. t.v:upper() .. " is a GW-BASIC command typed at the prompt, not a statement)")
  end
  if t.t == "id" then
    -- assignment, or a SUB call without CALL
    if P.prog.subs[t.v] and not P:is_op("=", 1) then
      P.pos = P.pos + 1
      local args = {}
      if not P:at_end() then
        repeat args[#args + 1] = P:expr() until not P:accept_op(",")
      end
      return add(P, { k = "call", name = t.v, args = args, text = t.text })
    end
    local target = P:lvalue()
    if not P:accept_op("=") then P:err() end
    return add(P, { k = "let", target = target, expr = P:expr() })
  end
  if t.t ~= "kw" then P:err() end
  P.pos = P.pos + 1
  local w = t.v
  if STMT[w] then return STMT[w](P, in_if) end
  if NOT_STATEMENTS[w] then P:err() end
  if K.UNSUPPORTED_STMTS[w] then P:unsupported(K.UNSUPPORTED_STMTS[w]) end
  if K.FUNCS[w] then P:err() end
  P:unsupported(w:upper())
end

-- ---- lines --------------------------------------------------------------------------------
local function direct_line(prog, i)
  local l = prog.lines[i]
  local w = l:match("^%s*(%a+)")
  if not (w and DIRECT[w:lower()] and prog.numbered) then return false end
  local rest = l:sub(#l:match("^%s*%a+") + 1)
  if rest:match("^%s*=") or rest:match("^%s*%(") or rest:match("^[%w$%%!#&.]") then return false end
  prog.direct[#prog.direct + 1] = { line = i, text = l:match("^%s*(.-)%s*$") }
  return true
end

local function parse_lines(P, all_toks)
  local prog = P.prog
  for i = 1, #prog.lines do
    P.lineno = i
    P.toks, P.pos = all_toks[i], 1
    if direct_line(prog, i) then goto next_line end
    local t = P:peek()
    if P.in_type then
      type_line(P)
      if P:peek().t ~= "eol" then P:err() end
      goto next_line
    end
    if t.t == "num" then
      P.pos = P.pos + 1
      record_label(P, P:label_name(t))
    elseif t.t == "id" and not t.sfx and P:is_op(":", 1) and not prog.subs[t.v] then
      P.pos = P.pos + 2
      record_label(P, t.v)
    end
    parse_stmt_list(P, nil, false)
    ::next_line::
  end
  if P.in_type then P:err("TYPE without END TYPE", P.in_type.line) end
  local cur = P.cur_proc
  if cur then
    P:err(cur.kind == "sub" and "SUB without END SUB" or cur.kind == "function"
      and "FUNCTION without END FUNCTION" or "DEF without END DEF", cur.line)
  end
end

-- the labels of DATA, and the statements nested into blocks
local function finish(prog)
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
end

function M.parse(source)
  local prog = { lines = split_lines(source), main = {}, procs = {}, data = {},
    data_labels = {}, labels = {}, label_list = {}, option_base = 0, types = {} }
  prog.direct = {}
  -- the metacommand $INCLUDE (in a comment: ' $INCLUDE: 'QB.BI'): pointcalc reads no other
  -- file while translating; the program is told on standard error when it starts
  prog.includes = {}
  for i, l in ipairs(prog.lines) do
    local low = l:lower()
    if low:match("^%s*%d*%s*'%s*%$include") or low:match("^%s*%d*%s*rem%s+%$include") then
      prog.includes[#prog.includes + 1] = { line = i, file = l:match("%$%a+%s*:?%s*'?([^']*)") }
    end
  end
  for _, l in ipairs(prog.lines) do
    if l:match("^%s*%d") then prog.numbered = true break end   -- a GW-BASIC listing
  end
  local all_toks = lex_all(prog)
  local P = expr_parser.cursor(prog)
  P.body = prog.main               -- where statements go
  parse_lines(P, all_toks)
  finish(prog)
  return prog
end

return M
