-- QBasic front end, pass 5: emit.  The resolved program (typed, named, its control flow
-- checked) becomes Lua source, one function per statement kind in STMT below; expressions are
-- qbasic_emit_expr's, the screen's statements qbasic_emit_gfx's, the blocks (loops, IF and
-- SELECT, structured or lowered to gotos) and the error trap's code qbasic_emit_blocks'.
--
-- The Lua keeps the program's lines: the code for source line N sits on Lua line N, followed
-- by the source line as a comment, so runtime errors name the QBasic line.  Variables of the
-- module are fields of the program's environment (_ENV, made by qbasic_rt), SUB and FUNCTION
-- variables are Lua locals.  The whole program is one function, run by `run` from qbasic_rt;
-- SUB, FUNCTION, DEF FN and GOSUB subroutines are defined before the program starts through a
-- chain of gotos ("def_" and "skip_" labels), since QBasic procedures may follow their callers.
local X = require "qbasic_emit_expr"
local G = require "qbasic_emit_gfx"
local control = require "qbasic_control"
local rt = require "qbasic_rt"
local K = require "qbasic_keywords"
local walk = require "qbasic_walk"
local lex = require "qbasic_lex"

local M = {}

local value, convert = X.value, X.convert

local label_lua = control.label_lua
local emit_block
local B = require "qbasic_emit_blocks"
local exit_loop, temp, locals_slot, trapped_code = B.exit_loop, B.temp, B.locals_slot, B.trapped_code

-- the Lua function of a GOSUB target: the module's, or the procedure's own
local function gosub_lua(S, label)
  return (S.cur_proc and S.cur_proc.gosub_lua or S.prog.gosub_lua)[label]
end

-- a SUB returns the parameters it changes, for the caller to copy back
local function copy_out(proc)
  local t = {}
  for i, p in ipairs(proc.params) do
    if proc.modified[i] and not p.array then t[#t + 1] = p.lua end
  end
  return table.concat(t, ", ")
end

-- what a procedure returns: a SUB its changed parameters, a FUNCTION its result and then those
local function returned(proc)
  local out = copy_out(proc)
  if proc.kind == "sub" then return out end
  if proc.kind ~= "function" or out == "" then return proc.result end   -- DEF FN: by value
  return proc.result .. ", " .. out
end

local function emit_call(S, st)
  local proc = S.prog.proc_by_name[st.name]
  local args = X.call_args(proc, st.args)
  local targets, any = {}, false
  for i, p in ipairs(proc.params) do
    if proc.modified[i] and not p.array then
      local a = st.args[i]
      if (a.k == "var" and not a.const) or a.k == "index" then
        targets[#targets + 1] = X.lvalue(a)
        any = true
      else
        targets[#targets + 1] = "_"
      end
    end
  end
  while targets[#targets] == "_" do targets[#targets] = nil end
  if any then
    S.E(st.line, table.concat(targets, ", ") .. " = " .. proc.lua .. "(" .. args .. ")")
  else
    S.E(st.line, proc.lua .. "(" .. args .. ")")
  end
end

-- the value of a numeric literal, possibly negated, or nil
local function end_program(S)
  if S.cur_proc or S.cur_region then
    S.uses_stop = true
    return "stop()"
  end
  return "do return end"
end

-- ---- the statements, one function each ---------------------------------------------------
local STMT = {}
function STMT.label(S, st)
  if S.prog.goto_targets[st.name] then S.E(st.line, "::" .. label_lua(st.name) .. "::") end
  if st.name:match("^%d+$") then S.erl = st.name end   -- ERL: the last line number before
end
-- ON ERROR GOTO label | 0, RESUME: the handler is a subroutine (qbasic_control) the runtime's
-- trap calls; RESUME returns what to do to the trap, which runs the failed statement again,
-- goes on after it, or returns the label for the statement's own code to jump to
function STMT.onerror(S, st)
  S.E(st.line, "on_error(" .. (st.label and S.prog.gosub_lua[st.label] or "nil") .. ")")
end
function STMT.resume(S, st)
  local what = st.what == "label" and st.label or st.what
  local code = "resume_ok(" .. X.lua_string(what) .. ")"
  if S.cur_region and S.cur_region.handler then code = "do return " .. code .. " end" end
  S.E(st.line, code)
end
function STMT.let(S, st)
  S.E(st.line, X.lvalue(st.target) .. " = " .. X.store(st.expr, st.target))
end
STMT["for"], STMT["while"], STMT["do"] = B.emit_for, B.emit_while, B.emit_do
STMT.ifb, STMT.if1, STMT.select = B.emit_ifb, B.emit_if1, B.emit_select
STMT["goto"] = function(S, st)
  if st.leaves_handler then   -- out of the error handler: as RESUME label (qbasic_control)
    S.E(st.line, "do return resume_ok(" .. X.lua_string(st.label) .. ") end")
  else
    S.E(st.line, "goto " .. label_lua(st.label))
  end
end
-- In dispatch mode (qbasic_control) the module's GOSUB is a jump that pushes where to come
-- back (the label gr<k>), and RETURN pops it and jumps to the dispatch at the end of the
-- module's code, which jumps back
local function dispatched(S, label)
  local gl = (S.cur_proc or S.prog).gosub_labels
  return gl and gl[label]
end
-- the GOSUB stack: the program's, or in a procedure a local one of each call
local function stack_arg(S) return S.cur_proc and ", _gs" or "" end
local function gosub_code(S, label, k)
  if dispatched(S, label) then
    if S.cur_region then
      error({ qb = true, line = S.line, msg = "GOSUB " .. label .. " inside an error handler of a "
        .. "program whose GOTOs cross its GOSUB subroutines: not supported by pointcalc" }, 0)
    end
    return "gosub_push(" .. k .. stack_arg(S) .. ") goto " .. label_lua(label)
  end
  return gosub_lua(S, label) .. "()"
end
local function return_label(S)
  S.gret_count = S.gret_count + 1
  S.gret.list[#S.gret.list + 1] = S.gret_count
  return S.gret_count
end
-- the dispatch of RETURN: back after the GOSUB that pushed k (g: the function's GOSUBs)
local function return_dispatch(g)
  local t = { "::gret::" }
  for i, k in ipairs(g.list) do
    t[#t + 1] = (i == 1 and "if " or "elseif ") .. g.var .. " == " .. k .. " then goto gr" .. k
  end
  if #g.list > 0 then t[#t + 1] = "end" end
  return table.concat(t, " ")
end
function STMT.gosub(S, st)
  S.line = st.line
  if dispatched(S, st.label) then
    local k = return_label(S)
    S.E(st.line, gosub_code(S, st.label, k) .. " ::gr" .. k .. "::")
  else
    S.E(st.line, gosub_code(S, st.label))
  end
end
function STMT.on(S, st)
  S.line = st.line
  local parts = { "do local on = on_index(" .. value(st.expr, 0) .. ")" }
  local k = st.gosub and (S.cur_proc or S.prog).gosub_labels and return_label(S)
  for i, l in ipairs(st.labels) do
    local act = st.gosub and gosub_code(S, l, k) or ("goto " .. label_lua(l))
    parts[#parts + 1] = (i == 1 and "if" or "elseif") .. " on == " .. i .. " then " .. act
  end
  parts[#parts + 1] = "end end"
  if k then parts[#parts + 1] = "::gr" .. k .. "::" end
  S.E(st.line, table.concat(parts, " "))
end
STMT["return"] = function(S, st)
  if st.label and not S.cur_region then   -- RETURN line: the dispatch mode's (qbasic_control)
    S.E(st.line, "gosub_pop(" .. stack_arg(S):sub(3) .. ") goto " .. label_lua(st.label))
  elseif S.cur_region and st.label then
    error({ qb = true, line = st.line, msg = "RETURN " .. st.label .. " inside an error handler: "
      .. "not supported by pointcalc" }, 0)
  elseif S.cur_region then S.E(st.line, "do return end")
  elseif (S.cur_proc or S.prog).gosub_labels then
    local g = S.gret
    if not g.var then g.var = temp(S) end
    g.used = true
    S.E(st.line, g.var .. " = gosub_pop(" .. stack_arg(S):sub(3) .. ") goto gret")
  else S.E(st.line, "return_without_gosub()") end
end
STMT["end"] = function(S, st) S.E(st.line, end_program(S)) end
function STMT.exit(S, st)
  if st.what == "for" or st.what == "do" then
    S.E(st.line, exit_loop(S, st.what))
  else
    local p = S.cur_proc
    local ret = returned(p)
    S.E(st.line, "do return" .. (ret ~= "" and (" " .. ret) or "") .. " end")
  end
end
-- the initial value of a scalar that needs one: a fixed-length string (NUL bytes, as QBasic
-- leaves it), a record
local function initial(d)
  if d.fixed then return "fixed_init(" .. d.fixed .. ")" end
  if K.is_record(d.ty) then return "record(" .. X.lua_string(d.ty:sub(5)) .. ")" end
end
-- the array constructor of a declaration, and its extra first argument
local function array_maker(d)
  if d.fixed then return "dim_fixed", d.fixed .. ", " end
  if K.is_record(d.ty) then return "dim_rec", X.lua_string(d.ty:sub(5)) .. ", " end
  return d.ty == "string" and "dim_str" or "dim", ""
end
function STMT.dim(S, st)
  for _, d in ipairs(st.decls) do
    local node = { k = d.bounds and "dimarray" or "dimvar", name = d.name, ty = d.ty,
      text = d.text, proc = S.cur_proc }
    -- STATIC (or DIM in a STATIC procedure): the variable is made on the first call only
    local once = S.cur_proc and S.prog.classify(node) == "static"
    local function init(code)
      if once then code = "if static_new(" .. X.lua_string(S.prog.lua_name(node)) .. ") then "
        .. code .. " end" end
      S.E(st.line, code)
    end
    if not d.bounds then
      local v = initial(d)
      if v then init(S.prog.lua_name(node) .. " = " .. v) end
    else
      local bs = {}
      for _, b in ipairs(d.bounds) do
        if b.lo then
          bs[#bs + 1] = "{" .. value(b.lo, 0) .. ", " .. value(b.hi, 0) .. "}"
        elseif st.base == 1 then
          bs[#bs + 1] = "{1, " .. value(b.hi, 0) .. "}"
        else
          bs[#bs + 1] = value(b.hi, 0)
        end
      end
      local f, first = array_maker(d)
      init(S.prog.lua_name(node) .. " = " .. f .. "(" .. first .. table.concat(bs, ", ") .. ")")
    end
  end
end
STMT.static = STMT.dim
function STMT.erase(S, st)
  for _, a in ipairs(st.arrays) do S.E(st.line, "erase(" .. S.prog.lua_name(a) .. ")") end
end
function STMT.midset(S, st)
  local t = X.lvalue(st.target)
  S.E(st.line, t .. " = mid_set(" .. t .. ", " .. value(st.start, 0) .. ", "
    .. (st.len and value(st.len, 0) or "nil") .. ", " .. value(st.expr, 0) .. ")")
end
function STMT.const(S, st)
  for _, d in ipairs(st.decls) do
    S.E(st.line, S.prog.const_lua[d.const.name] .. " = " .. convert(d.expr, d.const.ty))
  end
end
function STMT.read(S, st)
  for _, t in ipairs(st.targets) do
    local src = t.ty == "string" and "read_string()" or "read_number()"
    local code
    if t.ty == "string" or t.ty == "double" then code = src
    elseif t.ty == "single" then code = "csng(" .. src .. ")"
    elseif t.ty == "int" then code = "cint(" .. src .. ")"
    else code = "clng(" .. src .. ")" end
    if t.fixed then code = "fixstr(" .. code .. ", " .. t.fixed .. ")" end
    S.E(st.line, X.lvalue(t) .. " = " .. code)
  end
end
function STMT.restore(S, st)
  S.E(st.line, st.label and ("restore(" .. X.lua_string(st.label) .. ")") or "restore()")
end
STMT.call = emit_call
function STMT.randomize(S, st) S.E(st.line, "randomize(" .. value(st.expr, 0) .. ")") end
-- ---- files (qbasic_files.lua) --------------------------------------------------------------
STMT.finput = function(_, st) return G.input(st) end
function STMT.close(S, st)
  local t = {}
  for i, a in ipairs(st.files) do t[i] = value(a, 0) end
  S.E(st.line, "close_files(" .. table.concat(t, ", ") .. ")")
end
-- a value PRINT would mark as DOUBLE or LONG (WRITE prints them with their own digits)
local function marked(e)
  if e.ty == "double" then return "dbl(" .. value(e, 0, true) .. ")" end
  if e.ty == "long" then return "lng(" .. value(e, 0) .. ")" end
  return (value(e, 0))
end
function STMT.write(S, st)
  local t = { st.file and value(st.file, 0) or "nil" }
  for _, v in ipairs(st.values) do t[#t + 1] = marked(v) end
  S.E(st.line, "write_items(" .. table.concat(t, ", ") .. ")")
end
-- the bytes of a variable in a record: a number type, a fixed-length or ordinary string, a
-- TYPE's fields in order
local function layout(S, ty, fixed)
  if fixed then return "{fix = " .. fixed .. "}" end
  if ty == "string" then return '"str"' end
  if K.is_record(ty) then
    local def = S.prog.types[ty:sub(5)]
    local t = {}
    for _, f in ipairs(def.order) do
      local fd = def.fields[f]
      t[#t + 1] = "{" .. X.lua_string(f) .. ", " .. layout(S, fd.ty, fd.fixed) .. "}"
    end
    return "{" .. table.concat(t, ", ") .. "}"
  end
  return X.lua_string(ty)
end
function STMT.frecord(S, st)
  local args = { value(st.file, 0), st.record and value(st.record, 0) or "nil" }
  if not st.var then
    S.E(st.line, st.which .. "_record(" .. table.concat(args, ", ") .. ")")
    return
  end
  local v = X.lvalue(st.var)
  args[3], args[4] = layout(S, st.var.ty, st.var.fixed), v
  if st.which == "get" then
    S.E(st.line, v .. " = get_record(" .. table.concat(args, ", ") .. ")")
  else
    S.E(st.line, "put_record(" .. table.concat(args, ", ") .. ")")
  end
end
function STMT.field(S, st)
  local t = { (value(st.file, 0)) }
  for _, f in ipairs(st.fields) do
    if f.var.k ~= "var" or S.prog.classify(f.var) ~= "global" then
      error({ qb = true, line = st.line,
        msg = "FIELD of a procedure's variable or an array element: not supported by pointcalc" }, 0)
    end
    t[#t + 1] = "{" .. value(f.width, 0) .. ", " .. X.lua_string(S.prog.lua_name(f.var)) .. "}"
  end
  S.E(st.line, "field(" .. table.concat(t, ", ") .. ")")
end
-- COMMON: the values CHAIN passed (by position) into these variables
function STMT.common(S, st)
  local names = {}
  for _, item in ipairs(st.items) do names[#names + 1] = X.lua_string(S.prog.lua_name(item.node)) end
  S.E(st.line, "common({" .. table.concat(names, ", ") .. "})")
end
function STMT.palette_using(S, st)
  local idx = {}
  for i, a in ipairs(st.index) do idx[i] = value(a, 0) end
  S.E(st.line, "palette_using(" .. S.prog.lua_name(st.array) .. ", {" .. table.concat(idx, ", ") .. "})")
end
-- CLEAR: the module's variables (never its CONSTs or procedures) back to their first values
function STMT.clear(S, st)
  local names = {}
  for _, g in ipairs(S.prog.global_list) do names[#names + 1] = X.lua_string(g.lua) end
  S.E(st.line, "clear({" .. table.concat(names, ", ") .. "})")
end
function STMT.justify(S, st)
  local t = X.lvalue(st.target)
  S.E(st.line, t .. " = " .. (st.right and "rset" or "lset") .. "(" .. t .. ", " .. value(st.expr, 0) .. ")")
end
function STMT.swap(S, st)
  local a, b = X.lvalue(st.a), X.lvalue(st.b)
  S.E(st.line, a .. ", " .. b .. " = " .. b .. ", " .. a)
end
-- the screen's statements are qbasic_emit_gfx's (it writes through the E that install gave it)
local function gfx(g) return function(_, st) return g(st) end end
STMT.rtcall, STMT.getput, STMT.input, STMT.print = gfx(G.rtcall), gfx(G.getput), gfx(G.input),
  gfx(G.print)
STMT.print_using = gfx(G.print_using)
for _, k in ipairs({ "cls", "color", "palette", "pset", "preset", "line", "circle", "paint",
    "window", "view" }) do
  STMT[k] = gfx(G.gfx)
end
-- declarations that made their mark in the earlier passes, and DATA (collected at the end)
local NOTHING = { data = true, endsub = true, endfunction = true, enddef = true,
  shared = true, deftype = true }

local function emit_proc(S, st)
  local proc = st.proc
  local line = proc.line
  local params = {}
  for i, p in ipairs(proc.params) do params[i] = p.lua end
  local head = "goto " .. st.skip_label .. " ::" .. st.def_label .. ":: function " .. proc.lua
    .. "(" .. table.concat(params, ", ") .. ")"
  -- locals: numbers, strings, arrays
  local names, vals = {}, {}
  if proc.result then
    names[#names + 1] = proc.result
    vals[#vals + 1] = proc.ty == "string" and '""' or "0"
  end
  local arrays = {}
  for _, info in ipairs(proc.local_list) do
    if info.array then
      arrays[#arrays + 1] = info
    else
      names[#names + 1] = info.lua
      vals[#vals + 1] = info.ty == "string" and '""' or "0"
    end
  end
  local decl = ""
  if #names > 0 then decl = " local " .. table.concat(names, ", ") .. " = " .. table.concat(vals, ", ") end
  for _, a in ipairs(arrays) do
    if a.dimmed then
      decl = decl .. " local " .. a.lua
    else
      -- an array used without DIM: subscripts OPTION BASE..10 in each dimension
      local dims = {}
      for i = 1, a.rank or 1 do dims[i] = S.prog.option_base == 1 and "{1, 10}" or "10" end
      decl = decl .. " local " .. a.lua .. " = " .. (a.ty == "string" and "dim_str" or "dim")
        .. "(" .. table.concat(dims, ", ") .. ")"
    end
  end
  -- GOSUB subroutines of the procedure: local functions, defined before its first statement
  if proc.defs and #proc.defs > 0 then
    local fns = {}
    for i, d in ipairs(proc.defs) do fns[i] = d.lua end
    decl = decl .. " local " .. table.concat(fns, ", ") .. " goto " .. proc.defs[1].def_label
      .. " ::start::"
  end
  local saved_proc, saved_loops, saved_locals, saved_gret = S.cur_proc, S.loops, S.locals, S.gret
  S.gret = { list = {} }
  S.cur_proc = proc
  S.loops = { { kind = "fn" } }
  if proc.expr then
    local code = convert(proc.expr, proc.ty)
    -- a bare call would be a Lua tail call, and DEF FNa(x) = FNa(x + 1) would run forever
    -- instead of running out of stack space as QBasic does
    if code:match("^[%w_]+%b()$") then code = "(" .. code .. ")" end
    S.E(line, head .. decl .. " return " .. code .. " end goto "
      .. st.next_def .. " ::" .. st.skip_label .. "::")
  else
    S.E(line, head)
    locals_slot(S, line)
    if proc.gosub_labels then S.E(line, "local _gs = {}") end
    if decl ~= "" then S.E(line, decl:sub(2)) end
    emit_block(S, proc.tree)
    local ret = returned(proc)
    if S.gret.used then
      S.E(proc.end_line, "goto proc_end " .. return_dispatch(S.gret) .. " ::proc_end::")
    end
    S.E(proc.end_line, (ret ~= "" and ("return " .. ret .. " ") or "") .. "end goto " .. st.next_def
      .. " ::" .. st.skip_label .. "::")
  end
  S.cur_proc, S.loops, S.locals, S.gret = saved_proc, saved_loops, saved_locals, saved_gret
end

local function emit_region(S, r)
  local line = r.line
  S.E(line, "goto " .. r.skip_label .. " ::" .. r.def_label .. ":: " .. r.lua .. " = function()")
  local saved_loops, saved_locals = S.loops, S.locals
  locals_slot(S, line)
  S.loops = { { kind = "fn" } }
  S.cur_region = r
  emit_block(S, r.body)
  S.cur_region = nil
  S.loops, S.locals = saved_loops, saved_locals
  local end_line, tail
  if r.open_end then
    -- no RETURN: the subroutine runs to the end of the program, which it ends
    S.uses_stop = true
    end_line = r.end_line or #S.prog.lines
    tail = "stop() end goto " .. r.next_def .. " ::" .. r.skip_label .. ":: " .. r.lua
      .. "() return_without_gosub()"
  elseif r.return_line then
    end_line = r.return_line
    tail = "end goto " .. r.next_def .. " ::" .. r.skip_label .. ":: " .. r.lua
      .. "() return_without_gosub()"
  else
    -- runs into the next subroutine
    end_line = r.falls_into.line
    tail = "return " .. r.falls_into.lua .. "() end goto " .. r.next_def .. " ::" .. r.skip_label
      .. ":: " .. r.lua .. "() return_without_gosub()"
  end
  S.E(end_line, tail)
end

STMT.procdef, STMT.region = emit_proc, emit_region

-- In a program with an error handler, each statement of the module that can fail runs under
-- trap(function() ... end, ERL) (the runtime's); an error in a SUB or FUNCTION is trapped at
-- the module's statement that called it, as QBasic resumes there.
local TRAPPED = { let = true, print = true, print_using = true, rtcall = true, cls = true,
  color = true, palette = true, pset = true, preset = true, line = true, circle = true,
  paint = true, window = true, view = true, input = true, getput = true, call = true,
  dim = true, static = true, erase = true, midset = true, read = true, restore = true,
  randomize = true, swap = true, gosub = true, justify = true, palette_using = true,
  finput = true, close = true, write = true, frecord = true, field = true }
local function emit_trapped(S, st, f)
  local parts = {}
  local sink = S.sink
  S.sink = function(line, s)
    if line ~= st.line then error("internal: a trapped statement spans lines") end
    parts[#parts + 1] = s
  end
  f(S, st)
  S.sink = sink
  if #parts == 0 then return end
  S.E(st.line, trapped_code(S, table.concat(parts, " ")))
end

emit_block = function(S, list)
  for _, st in ipairs(list) do
    local f = STMT[st.k]
    if f then
      if S.trapping and not S.cur_proc and TRAPPED[st.k]
          and not (st.k == "gosub" and dispatched(S, st.label)) then emit_trapped(S, st, f)
      else f(S, st) end
    elseif not NOTHING[st.k] then error("cannot emit statement " .. st.k) end
  end
end
B.install(emit_block)

-- ---- the program ------------------------------------------------------------------------
-- The emitter's state S: the program, the Lua code of each source line (out, written by E),
-- the procedure and GOSUB subroutine being emitted, the open loops.
function M.emit(prog, chunkname)
  local out = {}
  for i = 1, #prog.lines do out[i] = {} end
  local S = { prog = prog, out = out, cur_proc = nil, cur_region = nil, exit_count = 0,
    uses_stop = false, loops = { { kind = "fn" } }, locals = {}, temp_count = 0, flat_count = 0,
    gret_count = 0, gret = { list = {} } }
  function S.sink(line, s) local o = out[line]; o[#o + 1] = s end
  function S.E(line, s) S.sink(line, s) end
  S.trapping, S.erl = next(prog.handlers) ~= nil, "0"
  X.install(prog)
  G.install(prog, S.E)
  emit_block(S, prog.main)
  if S.gret.used then S.E(#prog.lines, "do return end " .. return_dispatch(S.gret)) end
  return M.assemble(prog, chunkname, out, S.uses_stop, S.locals)
end

-- the code of one line: its pieces, a list of a lowered block's locals (locals_slot) as their
-- declaration
local function join(pieces)
  local t = {}
  for _, p in ipairs(pieces) do
    if type(p) == "table" then
      if #p > 0 then t[#t + 1] = "local " .. table.concat(p, ", ") end
      if p.table then t[#t + 1] = "local _ft = {}" end
    else
      t[#t + 1] = p
    end
  end
  return table.concat(t, " ")
end

-- ---- assembling the chunk -------------------------------------------------------------------
-- DATA items by line, the module's strings and arrays (undeclared strings are "", arrays
-- dimension themselves 0..10), the prelude on line 1 and `run`'s table on the last line
function M.assemble(prog, chunkname, out, uses_stop, main_locals)
  local lines = prog.lines
  local info = {}
  -- DATA, by line
  if #prog.data > 0 then
    local by_line, order = {}, {}
    for _, d in ipairs(prog.data) do
      if not by_line[d.line] then by_line[d.line] = {}; order[#order + 1] = d.line end
      local v
      if not d.quoted then
        local ok, tok = pcall(lex.line, d.text)
        local num
        if ok and #tok == 2 and tok[1].t == "num" then num = tok[1]
        elseif ok and #tok == 3 and tok[1].t == "op" and (tok[1].v == "-" or tok[1].v == "+")
            and tok[2].t == "num" then
          num = { v = tok[1].v == "-" and -tok[2].v or tok[2].v, text = d.text, ty = tok[2].ty }
        end
        if d.text == "" then v = '{0, ""}'        -- 0 for READ n, "" for READ s$
        elseif num and tonumber((d.text:gsub("[!#%%&]$", ""):gsub("[dD]", "e"))) then
          -- (a leading + is no Lua: DATA +5 is 5)
          v = d.text:gsub("[!#%%&]$", ""):gsub("[dD]", "e"):gsub("^%+%s*", "")
        elseif num then v = X.exact_text(num.v)
        else v = X.lua_string(d.text) end
        -- READ s$ of a number gets its text as written (DATA 007, 1.50): keep the text when
        -- the number's own text differs
        if num and num.v - num.v == 0 and rt.data_text(num.v) ~= d.text then
          v = "{" .. v .. ", " .. X.lua_string(d.text) .. "}"
        end
      else
        v = X.lua_string(d.text)
      end
      local t = by_line[d.line]
      t[#t + 1] = v
    end
    local parts = {}
    for _, l in ipairs(order) do parts[#parts + 1] = "[" .. l .. "] = {" .. table.concat(by_line[l], ", ") .. "}" end
    info[#info + 1] = "data = {" .. table.concat(parts, ", ") .. "}"
    local dl = {}
    local names = {}
    for name in pairs(prog.data_labels) do names[#names + 1] = name end
    table.sort(names)
    local used = {}
    local function scan_restore(st)
      if st.k == "restore" and st.label then used[st.label] = true end
    end
    walk.stmts(prog.main, scan_restore)
    for _, proc in ipairs(prog.procs) do
      if proc.tree then walk.stmts(proc.tree, scan_restore) end
    end
    for _, name in ipairs(names) do
      if used[name] then dl[#dl + 1] = "[" .. X.lua_string(name) .. "] = " .. prog.data_labels[name] end
    end
    if #dl > 0 then info[#info + 1] = "data_labels = {" .. table.concat(dl, ", ") .. "}" end
  end
  -- module strings and arrays (undeclared strings are "", arrays dimension themselves 0..10)
  local strs, arrs = {}, {}
  for _, g in ipairs(prog.global_list) do
    if g.array then
      arrs[#arrs + 1] = g.lua .. " = {" .. (g.rank or 1) .. (g.ty == "string" and ', "string"' or "") .. "}"
    elseif g.ty == "string" then
      strs[#strs + 1] = X.lua_string(g.lua)
    end
  end
  if #strs > 0 then info[#info + 1] = "strings = {" .. table.concat(strs, ", ") .. "}" end
  if #arrs > 0 then info[#info + 1] = "arrays = {" .. table.concat(arrs, ", ") .. "}" end
  if #arrs > 0 and prog.option_base == 1 then info[#info + 1] = "base = 1" end
  if uses_stop then info[#info + 1] = "stops = true" end
  -- TYPEs: the template of each record (0, "", NUL bytes, nested records)
  local tnames = {}
  for name in pairs(prog.types) do tnames[#tnames + 1] = name end
  table.sort(tnames)
  local function template(def)
    local parts = {}
    for _, f in ipairs(def.order) do
      local fd, v = def.fields[f], "0"
      if fd.fixed then v = X.lua_string(string.rep("\0", fd.fixed))
      elseif fd.ty == "string" then v = '""'
      elseif K.is_record(fd.ty) then v = template(prog.types[fd.ty:sub(5)]) end
      parts[#parts + 1] = "[" .. X.lua_string(f) .. "] = " .. v
    end
    return "{" .. table.concat(parts, ", ") .. "}"
  end
  if #tnames > 0 then
    local parts = {}
    for _, name in ipairs(tnames) do
      parts[#parts + 1] = "[" .. X.lua_string(name) .. "] = " .. template(prog.types[name])
    end
    info[#info + 1] = "types = {" .. table.concat(parts, ", ") .. "}"
  end

  local prelude = "local _ENV = require(\"qbasic_rt\").new(_ENV, " .. X.lua_string(chunkname)
    .. ") return run(function()"
  if #prog.direct > 0 then
    -- GW-BASIC direct-mode lines: named on standard error when the program starts
    local t = {}
    for _, d in ipairs(prog.direct) do t[#t + 1] = d.line .. ", " .. X.lua_string(d.text) end
    prelude = prelude .. " direct_lines(" .. table.concat(t, ", ") .. ")"
  end
  if #prog.includes > 0 then
    local t = {}
    for _, d in ipairs(prog.includes) do t[#t + 1] = d.line .. ", " .. X.lua_string(d.file) end
    prelude = prelude .. " skipped_includes(" .. table.concat(t, ", ") .. ")"
  end
  if main_locals and #main_locals > 0 then prelude = prelude .. " " .. join({ main_locals }) end
  if #prog.defs > 0 then prelude = prelude .. " goto " .. prog.defs[1].def_label .. " ::start::" end
  local result = {}
  for i = 1, #lines do
    local code = join(out[i])
    if i == 1 then code = prelude .. (code ~= "" and (" " .. code) or "") end
    if i == #lines then
      code = code .. (code ~= "" and " " or "") .. "end, {" .. table.concat(info, ", ") .. "})"
    end
    local src = lines[i]
    local text
    if src:match("^%s*$") then
      text = code
    elseif code == "" then
      text = "-- " .. src
    else
      -- the source's indentation, then the code, then the source line
      if i > 1 then code = src:match("^[ \t]*") .. code end
      text = code .. "  -- " .. src
    end
    result[i] = text
  end
  return table.concat(result, "\n") .. "\n"
end

return M
