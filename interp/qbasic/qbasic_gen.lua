-- QBasic front end, part 3: block structure and Lua emission.
--
-- The Lua keeps the program's lines: the code for source line N sits on Lua line N, followed
-- by the source line as a comment, so runtime errors name the QBasic line.  Variables of the
-- module are fields of the program's environment (_ENV, made by qbasic_rt), SUB and FUNCTION
-- variables are Lua locals.  The whole program is one function, run by `run` from qbasic_rt;
-- SUB, FUNCTION, DEF FN and GOSUB subroutines are defined before the program starts through a
-- chain of gotos ("def_" and "skip_" labels), since QBasic procedures may follow their callers.
local parse = require "qbasic_parse"
local rt = require "qbasic_rt"

local M = {}

local SFX = parse.SUFFIX_OF_TYPE
local NUM_RANK = { int = 1, long = 2, single = 3, double = 4 }
local SFX_NAME = { int = "i", long = "l", single = "f", double = "d", string = "s" }

local LUA_KEYWORDS = {}
for w in ([[and break do else elseif end false for function goto if in local nil not or
  repeat return then true until while]]):gmatch("%S+") do LUA_KEYWORDS[w] = true end

local function qerr(msg, line) error({ qb = true, msg = msg, line = line }, 0) end

-- ---- block structure ------------------------------------------------------------------------

local CLOSE_ERRORS = { ["for"] = "FOR without NEXT", ["while"] = "WHILE without WEND",
  ["do"] = "DO without LOOP", ["if"] = "Block IF without END IF",
  ["select"] = "SELECT without END SELECT" }

-- move labels written on a closing line (END IF, ELSE, CASE...) out of the branch before it
local function take_trailing_labels(body, line)
  local moved = {}
  while #body > 0 and body[#body].k == "label" and body[#body].line == line do
    table.insert(moved, 1, table.remove(body))
  end
  return moved
end

local function build(list)
  local root = {}
  local stack = { { kind = "root", body = root } }
  local function top() return stack[#stack] end
  local function append(st) local b = top().body
    if not b then qerr("Syntax error", st.line) end   -- a statement between SELECT and CASE
    b[#b + 1] = st
  end
  for _, st in ipairs(list) do
    local k = st.k
    if k == "for" then
      local node = { k = "for", var = st.var, from = st.from, to = st.to, step = st.step,
        line = st.line, body = {} }
      append(node)
      stack[#stack + 1] = { kind = "for", node = node, body = node.body }
    elseif k == "next" then
      local t = top()
      if t.kind ~= "for" then qerr("NEXT without FOR", st.line) end
      if st.var and (st.var.name ~= t.node.var.name or st.var.ty ~= t.node.var.ty) then
        qerr("NEXT without FOR", st.line)
      end
      t.node.next_line = st.line
      stack[#stack] = nil
    elseif k == "while" then
      local node = { k = "while", cond = st.cond, line = st.line, body = {} }
      append(node)
      stack[#stack + 1] = { kind = "while", node = node, body = node.body }
    elseif k == "wend" then
      if top().kind ~= "while" then qerr("WEND without WHILE", st.line) end
      top().node.end_line = st.line
      stack[#stack] = nil
    elseif k == "do" then
      local node = { k = "do", cond_top = st.cond, line = st.line, body = {} }
      append(node)
      stack[#stack + 1] = { kind = "do", node = node, body = node.body }
    elseif k == "loop" then
      if top().kind ~= "do" then qerr("LOOP without DO", st.line) end
      local node = top().node
      if st.cond and node.cond_top then qerr("Syntax error", st.line) end
      node.cond_bottom = st.cond
      node.end_line = st.line
      stack[#stack] = nil
    elseif k == "ifblock" then
      local node = { k = "ifb", line = st.line, branches = { { cond = st.cond, body = {},
        line = st.line } } }
      append(node)
      stack[#stack + 1] = { kind = "if", node = node, body = node.branches[1].body }
    elseif k == "elseif" or k == "else" then
      local t = top()
      if t.kind ~= "if" or t.node.else_body then
        qerr(k == "else" and "ELSE without IF" or "ELSEIF without IF", st.line)
      end
      local moved = take_trailing_labels(t.body, st.line)
      if k == "elseif" then
        local br = { cond = st.cond, body = moved, line = st.line }
        t.node.branches[#t.node.branches + 1] = br
        t.body = br.body
      else
        t.node.else_body = moved
        t.node.else_line = st.line
        t.body = t.node.else_body
      end
    elseif k == "endif" then
      local t = top()
      if t.kind ~= "if" then qerr("END IF without block IF", st.line) end
      local moved = take_trailing_labels(t.body, st.line)
      t.node.end_line = st.line
      stack[#stack] = nil
      for _, l in ipairs(moved) do append(l) end
    elseif k == "select" then
      local node = { k = "select", expr = st.expr, line = st.line, cases = {} }
      append(node)
      stack[#stack + 1] = { kind = "select", node = node, body = nil }
    elseif k == "case" then
      local t = top()
      if t.kind ~= "select" or t.node.else_body then qerr("CASE without SELECT", st.line) end
      local moved = t.body and take_trailing_labels(t.body, st.line) or {}
      if st.is_else then
        t.node.else_body = moved
        t.node.else_line = st.line
        t.body = t.node.else_body
      else
        local c = { tests = st.tests, body = moved, line = st.line }
        t.node.cases[#t.node.cases + 1] = c
        t.body = c.body
      end
    elseif k == "endselect" then
      local t = top()
      if t.kind ~= "select" then qerr("END SELECT without SELECT", st.line) end
      local moved = t.body and take_trailing_labels(t.body, st.line) or {}
      t.node.end_line = st.line
      stack[#stack] = nil
      for _, l in ipairs(moved) do append(l) end
    elseif k == "if1" then
      local node = { k = "if1", cond = st.cond, line = st.line,
        then_body = build(st.then_body),
        else_body = st.else_body and build(st.else_body) }
      append(node)
    elseif k == "label" then
      -- a label in a SELECT before the first CASE: keep it before the SELECT
      if not top().body then
        local sel = top().node
        local parent = stack[#stack - 1].body
        table.insert(parent, #parent, st)
        sel.pre_labels = true
      else
        append(st)
      end
    elseif k == "endsub" or k == "endfunction" or k == "enddef" then
      append(st)
    else
      if st.k == "procdef" and #stack > 1 then
        qerr((st.proc.kind == "sub" and "SUB" or st.proc.kind == "function" and "FUNCTION"
          or "DEF FN") .. " inside a block", st.line)
      end
      append(st)
    end
  end
  if #stack > 1 then
    local t = stack[#stack]
    qerr(CLOSE_ERRORS[t.kind], t.node.line)
  end
  return root
end

-- ---- visiting expressions ------------------------------------------------------------------

local function walk_expr(e, fn)
  if not e then return end
  fn(e)
  local k = e.k
  if k == "bin" or k == "rel" or k == "logic" then walk_expr(e.a, fn); walk_expr(e.b, fn)
  elseif k == "neg" or k == "not" or k == "paren" then walk_expr(e.a, fn)
  elseif k == "index" or k == "call" or k == "ucall" or k == "fncall" then
    for _, a in ipairs(e.args) do walk_expr(a, fn) end
  end
end

-- every expression (and lvalue) of a statement of a flat list, single-line IF bodies included
local function walk_stmt(st, fn)
  local function x(e) walk_expr(e, fn) end
  local k = st.k
  if k == "let" then x(st.target); x(st.expr)
  elseif k == "print" then for _, it in ipairs(st.items) do x(it.e) end
  elseif k == "dim" then
    for _, d in ipairs(st.decls) do
      fn({ k = d.bounds and "dimarray" or "dimvar", decl = d, proc = st.proc })
      for _, b in ipairs(d.bounds or {}) do x(b.lo); x(b.hi) end
    end
  elseif k == "const" then for _, d in ipairs(st.decls) do x(d.expr) end
  elseif k == "read" then for _, t in ipairs(st.targets) do x(t) end
  elseif k == "for" then x(st.var); x(st.from); x(st.to); x(st.step)
  elseif k == "next" then x(st.var)
  elseif k == "if1" then
    x(st.cond)
    for _, s in ipairs(st.then_body) do walk_stmt(s, fn) end
    for _, s in ipairs(st.else_body or {}) do walk_stmt(s, fn) end
  elseif k == "ifblock" or k == "elseif" or k == "while" then x(st.cond)
  elseif k == "do" or k == "loop" then if st.cond then x(st.cond.e) end
  elseif k == "select" or k == "on" or k == "randomize" then x(st.expr)
  elseif k == "case" then
    for _, t in ipairs(st.tests or {}) do x(t.e); x(t.lo); x(t.hi) end
  elseif k == "call" then for _, a in ipairs(st.args) do x(a) end
  elseif k == "screen" then x(st.mode)
  elseif k == "cls" then x(st.arg)
  elseif k == "color" then x(st.fg); x(st.bg)
  elseif k == "palette" then x(st.attr); x(st.color)
  elseif k == "pset" or k == "preset" then x(st.p.x); x(st.p.y); x(st.color)
  elseif k == "line" then
    if st.p1 then x(st.p1.x); x(st.p1.y) end
    x(st.p2.x); x(st.p2.y); x(st.color)
  elseif k == "circle" then
    x(st.p.x); x(st.p.y); x(st.r); x(st.color); x(st.a0); x(st.a1); x(st.aspect)
  elseif k == "paint" then x(st.p.x); x(st.p.y); x(st.color); x(st.border)
  elseif k == "window" or k == "view" then
    if st.p1 then x(st.p1.x); x(st.p1.y); x(st.p2.x); x(st.p2.y) end
    x(st.fill); x(st.border)
  elseif k == "swap" then x(st.a); x(st.b)
  elseif k == "rtcall" then for i = 1, st.nargs do x(st.args[i]) end
  elseif k == "getput" then
    x(st.p1.x); x(st.p1.y)
    if st.p2 then x(st.p2.x); x(st.p2.y) end
    fn(st.array)
    for _, a in ipairs(st.index) do x(a) end
  elseif k == "input" then for _, t in ipairs(st.targets) do x(t) end
  end
end

-- ---- literals ----------------------------------------------------------------------------

local f32 = require("pointcalc").qb.f32     -- SINGLE rounding (stdlib/geom/qbnum.c)

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

-- ---- the generator --------------------------------------------------------------------------

function M.generate(prog, chunkname)
  local lines = prog.lines
  local out = {}
  for i = 1, #lines do out[i] = {} end
  local function E(line, s) local o = out[line]; o[#o + 1] = s end

  -- structure
  local main_tree = build(prog.main)
  for _, proc in ipairs(prog.procs) do
    if proc.kind ~= "deffn" or not proc.expr then
      -- the closing END SUB/FUNCTION/DEF is the last statement of the flat body
      local b = proc.body
      if b[#b] and (b[#b].k == "endsub" or b[#b].k == "endfunction" or b[#b].k == "enddef") then
        b[#b] = nil
      end
      proc.tree = build(b)
    end
  end

  -- ---- names -------------------------------------------------------------------------------
  local helper_names = rt.names
  local function new_ns()
    local ns = {}
    for w in pairs(LUA_KEYWORDS) do ns[w] = true end
    for _, w in ipairs(helper_names) do ns[w:lower()] = true end
    return ns
  end
  local gns = new_ns()
  local function clean(text, name)
    local t = (text or name):gsub("[%$%%&!#]$", ""):gsub("%.", "_")
    return t
  end
  local function alloc(ns, cands)
    for _, c in ipairs(cands) do
      if not ns[c:lower()] then ns[c:lower()] = true; return c end
    end
    local base = cands[1]
    local i = 2
    while ns[(base .. "_" .. i):lower()] do i = i + 1 end
    ns[(base .. "_" .. i):lower()] = true
    return base .. "_" .. i
  end

  -- procedures, DEF FNs and CONSTs first: they are the program's global functions/values
  local proc_by_name, fn_by_name = {}, {}
  for _, proc in ipairs(prog.procs) do
    if proc.kind == "deffn" then
      if fn_by_name[proc.name] then qerr("Duplicate definition", proc.line) end
      fn_by_name[proc.name] = proc
    else
      if proc_by_name[proc.name] then qerr("Duplicate definition", proc.line) end
      proc_by_name[proc.name] = proc
    end
    proc.lua = alloc(gns, { clean(proc.text, proc.name) })
  end
  local const_lua = {}
  for name, c in pairs(prog.consts) do c.key = name end
  local const_list = {}
  for _, c in pairs(prog.consts) do const_list[#const_list + 1] = c end
  table.sort(const_list, function(a, b) return a.line < b.line end)
  for _, c in ipairs(const_list) do const_lua[c.name] = alloc(gns, { clean(c.text, c.name) }) end

  -- which variables are module (global) variables, which are procedure locals
  local function key_of(node)
    local arr = node.k == "index" or node.k == "arrayref" or node.k == "dimarray"
    return (arr and "()" or "") .. node.name .. SFX[node.ty], arr
  end
  for _, proc in ipairs(prog.procs) do
    proc.paramkeys = {}
    for i, p in ipairs(proc.params) do
      p.key = (p.array and "()" or "") .. p.name .. SFX[p.ty]
      p.index = i
      proc.paramkeys[p.key] = p
    end
    proc.locals, proc.local_list, proc.global_refs = {}, {}, {}
  end
  local function is_shared(proc, node)
    local arr = node.k == "index" or node.k == "arrayref" or node.k == "dimarray"
    local sc = proc.scope.shared
    if arr then
      return sc["()" .. node.name] or prog.shared_arrays[node.name]
    end
    return sc[node.name] or prog.shared[node.name]
  end
  -- classify: returns "const", "param", "global" or "local"
  local function classify(node)
    if node.const then return "const" end
    local proc = node.proc
    if not proc then return "global" end
    local key = key_of(node)
    if proc.paramkeys[key] then return "param", proc.paramkeys[key] end
    if proc.kind == "deffn" then return "global" end
    if is_shared(proc, node) then return "global" end
    return "local"
  end

  local globals, global_list = {}, {}
  local function note(node)
    local k = node.k
    if k == "dimarray" or k == "dimvar" then
      local d = node.decl
      node = { k = k, name = d.name, ty = d.ty, text = d.text, proc = node.proc, decl = d }
    elseif k ~= "var" and k ~= "index" and k ~= "arrayref" then
      return
    end
    local class = classify(node)
    if class == "const" or class == "param" then return end
    local key, arr = key_of(node)
    local info
    if class == "global" then
      if node.proc then node.proc.global_refs[key] = true end
      info = globals[key]
      if not info then
        info = { key = key, array = arr, ty = node.ty, text = node.text, name = node.name,
          rank = nil, dimmed = false }
        globals[key] = info
        global_list[#global_list + 1] = info
      end
    else
      local proc = node.proc
      info = proc.locals[key]
      if not info then
        info = { key = key, array = arr, ty = node.ty, text = node.text, name = node.name,
          rank = nil, dimmed = false }
        proc.locals[key] = info
        proc.local_list[#proc.local_list + 1] = info
      end
    end
    if node.k == "index" and not info.rank then info.rank = #node.args end
    if node.k == "dimarray" then info.dimmed = true; info.rank = info.rank or #node.decl.bounds end
    if node.k == "index" and info.rank ~= #node.args then
      qerr("Wrong number of dimensions", node.line or 0)
    end
  end
  local function walk_flat(list, proc)
    for _, st in ipairs(list) do
      if st.k == "dim" then st.proc = proc end
      walk_stmt(st, function(e)
        if e.k == "dimarray" or e.k == "dimvar" then e.proc = proc end
        note(e)
      end)
    end
  end
  walk_flat(prog.main, nil)
  for _, proc in ipairs(prog.procs) do
    if proc.expr then walk_expr(proc.expr, note) end
    walk_flat(proc.body, proc)
  end

  -- global variable names: default-looking scalars first, then the others, then arrays
  local function var_cands(info)
    local base = clean(info.text, info.name)
    if info.array then return { base, base .. "_arr" } end
    return { base, base .. "_" .. SFX_NAME[info.ty] }
  end
  local function plain(info) return not info.text:match("[%$%%&!#]$") end
  for pass = 1, 3 do
    for _, info in ipairs(global_list) do
      local want = (pass == 1 and not info.array and plain(info))
        or (pass == 2 and not info.array and not plain(info)) or (pass == 3 and info.array)
      if want then info.lua = alloc(gns, var_cands(info)) end
    end
  end
  -- names of procedure locals
  for _, proc in ipairs(prog.procs) do
    local ns = new_ns()
    for _, p in ipairs(prog.procs) do ns[p.lua:lower()] = true end
    for _, l in pairs(const_lua) do ns[l:lower()] = true end
    -- module variables this procedure uses (SHARED, or any for DEF FN) keep their names
    for key in pairs(proc.global_refs) do ns[globals[key].lua:lower()] = true end
    for _, p in ipairs(proc.params) do
      p.lua = alloc(ns, { clean(p.text, p.name), clean(p.text, p.name) .. "_" .. SFX_NAME[p.ty] })
    end
    if proc.kind ~= "sub" and not proc.expr then proc.result = alloc(ns, { proc.lua .. "_result" }) end
    for pass = 1, 3 do
      for _, info in ipairs(proc.local_list) do
        local want = (pass == 1 and not info.array and plain(info))
          or (pass == 2 and not info.array and not plain(info)) or (pass == 3 and info.array)
        if want then info.lua = alloc(ns, var_cands(info)) end
      end
    end
  end

  local function lua_name(node)
    local class, p = classify(node)
    if class == "const" then return const_lua[node.const.name] end
    if class == "param" then return p.lua end
    local key = key_of(node)
    if class == "global" then return globals[key].lua end
    return node.proc.locals[key].lua
  end

  -- ---- procedure parameters changed inside (copy-back for SUBs) -----------------------------
  local function param_of(proc, node)
    if not proc or node.k ~= "var" or node.const then return nil end
    local class, p = classify(node)
    if class == "param" and node.proc == proc then return p end
  end
  for _, proc in ipairs(prog.procs) do
    proc.modified = {}
    local function mark(node) local p = param_of(proc, node); if p then proc.modified[p.index] = true end end
    local function scan(list)
      for _, st in ipairs(list) do
        if st.k == "let" then mark(st.target)
        elseif st.k == "for" then mark(st.var)
        elseif st.k == "read" then for _, t in ipairs(st.targets) do mark(t) end
        elseif st.k == "swap" then mark(st.a); mark(st.b)
        elseif st.k == "if1" then scan(st.then_body); scan(st.else_body or {}) end
      end
    end
    scan(proc.body)
  end
  -- passing a parameter on to a SUB that changes it changes it too
  local changed = true
  while changed do
    changed = false
    for _, proc in ipairs(prog.procs) do
      local function scan(list)
        for _, st in ipairs(list) do
          if st.k == "call" then
            local callee = proc_by_name[st.name]
            if callee then
              for i, a in ipairs(st.args) do
                local p = param_of(proc, a)
                if p and callee.modified[i] and not proc.modified[p.index] then
                  proc.modified[p.index] = true
                  changed = true
                end
              end
            end
          elseif st.k == "if1" then scan(st.then_body); scan(st.else_body or {}) end
        end
      end
      scan(proc.body)
    end
  end

  -- ---- GOSUB subroutines -------------------------------------------------------------------
  local gosub_targets = {}
  local function find_gosubs(list)
    for _, st in ipairs(list) do
      if st.k == "gosub" then gosub_targets[st.label] = st.line
      elseif st.k == "on" and st.gosub then
        for _, l in ipairs(st.labels) do gosub_targets[l] = st.line end
      elseif st.k == "if1" then find_gosubs(st.then_body); find_gosubs(st.else_body or {}) end
    end
  end
  find_gosubs(prog.main)
  for _, proc in ipairs(prog.procs) do
    local function check(list)
      for _, st in ipairs(list) do
        if st.k == "gosub" or (st.k == "on" and st.gosub) then
          qerr("GOSUB inside a SUB or FUNCTION: not supported by pointcalc", st.line)
        elseif st.k == "if1" then check(st.then_body); check(st.else_body or {}) end
      end
    end
    check(proc.body)
  end
  local gosub_lua = {}
  for label, line in pairs(gosub_targets) do
    local l = prog.labels[label]
    if not l or l.proc then qerr("Label not defined", line) end
    -- through the namespace: a variable gosub.10 (gosub_10 in Lua) gets another name
    gosub_lua[label] = alloc(gns, { "gosub_" .. label:gsub("%.", "_") })
  end
  -- split the top level of main into plain statements and subroutines
  local regions = {}
  do
    local newtop = {}
    local cur = nil
    for _, st in ipairs(main_tree) do
      if st.k == "label" and gosub_targets[st.name] then
        local r = { k = "region", label = st.name, lua = gosub_lua[st.name], line = st.line,
          body = { st } }
        if cur then cur.falls_into = r end
        cur = r
        regions[#regions + 1] = r
        newtop[#newtop + 1] = r
      elseif cur then
        if st.k == "return" then
          cur.return_line = st.line
          cur = nil
        elseif st.k == "procdef" then
          qerr("SUB or FUNCTION inside a GOSUB subroutine", st.line)
        else
          cur.body[#cur.body + 1] = st
        end
      else
        newtop[#newtop + 1] = st
      end
    end
    if cur then qerr("GOSUB subroutine without RETURN", cur.line) end
    main_tree = newtop
    -- a GOSUB target inside a block cannot be a subroutine
    for label, line in pairs(gosub_targets) do
      local found = false
      for _, r in ipairs(regions) do if r.label == label then found = true end end
      if not found then
        qerr("GOSUB " .. label .. ": the target must be at the top level of the program", line)
      end
    end
  end

  -- ---- the definition chain -----------------------------------------------------------------
  local defs = {}      -- in textual order: procs and regions
  local function collect_defs(list)
    for _, st in ipairs(list) do
      if st.k == "procdef" then defs[#defs + 1] = st
      elseif st.k == "region" then defs[#defs + 1] = st end
    end
  end
  collect_defs(main_tree)
  for i, d in ipairs(defs) do
    local name = d.k == "region" and d.lua or d.proc.lua
    d.def_label = "def_" .. name
    d.skip_label = "skip_" .. name
  end
  for i, d in ipairs(defs) do
    d.next_def = defs[i + 1] and defs[i + 1].def_label or "start"
  end

  -- ---- blocks, labels and gotos: checked after emission -------------------------------------
  local block_id = 0
  local path = {}
  local label_at, gotos = {}, {}
  local function open_block(is_fn)
    block_id = block_id + 1
    path[#path + 1] = is_fn and ("fn" .. block_id) or block_id
  end
  local function close_block() path[#path] = nil end
  local function copy_path() local c = {}; for i, v in ipairs(path) do c[i] = v end; return c end
  local goto_targets = {}
  local function scan_gotos(list)
    for _, st in ipairs(list) do
      if st.k == "goto" then goto_targets[st.label] = true
      elseif st.k == "on" and not st.gosub then
        for _, l in ipairs(st.labels) do goto_targets[l] = true end
      elseif st.k == "if1" then scan_gotos(st.then_body); scan_gotos(st.else_body or {}) end
    end
  end
  scan_gotos(prog.main)
  for _, proc in ipairs(prog.procs) do scan_gotos(proc.body) end
  local function label_lua(name)
    if name:match("^%d+$") then return "L" .. name end
    return "L_" .. name:gsub("%.", "_")
  end
  local function emit_goto(line, label)
    gotos[#gotos + 1] = { label = label, path = copy_path(), line = line }
    return "goto " .. label_lua(label)
  end

  -- ---- expressions --------------------------------------------------------------------------
  -- Lua precedences: or 1, and 2, comparison 3, .. 9, + - 10, * / 11, unary 12, ^ 14, atom 20
  local emit_value, emit_cond

  local function wrap(code, prec, min)
    if prec < min then return "(" .. code .. ")" end
    return code
  end

  local function is_lit(e) return e.k == "num" or (e.k == "paren" and is_lit(e.a)) end
  local function lit_value(e) if e.k == "paren" then return lit_value(e.a) end return e.v end
  local function strip(e) while e.k == "paren" do e = e.a end return e end

  -- does evaluating e have effects or possible errors (for AND/OR: QBasic evaluates both sides)
  local function effectful(e)
    local found = false
    walk_expr(e, function(n)
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

  local FN_LUA = { ["left$"] = "left", ["right$"] = "right", ["mid$"] = "mid", ["str$"] = "str",
    ["chr$"] = "chr", ["space$"] = "space", ["string$"] = "string_", ["lcase$"] = "lcase",
    ["ucase$"] = "ucase", ["ltrim$"] = "ltrim", ["rtrim$"] = "rtrim", ["hex$"] = "hex",
    ["oct$"] = "oct", ["inkey$"] = "inkey", ["input$"] = "input_chars", pos = "pos_",
    ["varptr$"] = "varptr" }

  local convert   -- convert(e, ty): code of e as a value of type ty (store rounding)

  local function args_code(args, exact)
    local t = {}
    for i, a in ipairs(args) do t[i] = (emit_value(a, 0, exact)) end
    return table.concat(t, ", ")
  end

  local function call_args(proc, args, line, what)
    if #args ~= #proc.params then qerr("Argument-count mismatch", line) end
    local t = {}
    for i, a in ipairs(args) do
      local p = proc.params[i]
      local s = a
      if p.array then
        if s.k ~= "arrayref" then qerr("Parameter type mismatch", line) end
        if s.ty ~= p.ty then qerr("Parameter type mismatch", line) end
        t[i] = lua_name(s)
      else
        if s.k == "arrayref" then qerr("Parameter type mismatch", line) end
        if (p.ty == "string") ~= (s.ty == "string") then qerr("Type mismatch", line) end
        if (s.k == "var" and not s.const) or s.k == "index" then
          -- a variable passed by reference must have the parameter's type
          if s.ty ~= p.ty then qerr("Parameter type mismatch", line) end
        end
        t[i] = convert(a, p.ty)
      end
    end
    return table.concat(t, ", ")
  end

  local function emit_index(e)
    local parts = { lua_name(e) }
    for _, a in ipairs(e.args) do parts[#parts + 1] = "[" .. emit_value(a, 0) .. "]" end
    return table.concat(parts)
  end

  -- emit_value(e, min, exact) -> code (parenthesised for precedence min)
  emit_value = function(e, min, exact)
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
      return emit_index(e), 20
    elseif k == "arrayref" then
      qerr("Syntax error", e.line)
    elseif k == "neg" then
      local ex = exact or e.ty == "double"
      local a = emit_value(e.a, 12, ex)
      if a:sub(1, 1) == "-" then a = "(" .. a .. ")" end
      return wrap("-" .. a, 12, min), 12
    elseif k == "bin" then
      local op = e.op
      local ex = exact or e.ty == "double"
      if e.ty == "string" then
        local code = emit_value(e.a, 10, ex) .. " .. " .. emit_value(e.b, 9, ex)
        return wrap(code, 9, min), 9
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
      return (FN_LUA[fn] or fn) .. "(" .. args_code(e.args, ex) .. ")", 20
    elseif k == "ucall" then
      local proc = proc_by_name[e.name]
      if not proc or proc.kind ~= "function" then qerr("Subprogram not defined", e.line) end
      for i, a in ipairs(e.args) do
        if proc.modified[i] and ((a.k == "var" and not a.const) or a.k == "index") then
          qerr("FUNCTION " .. proc.text .. " assigns to its parameter " .. proc.params[i].text
            .. ": pass the argument as (" .. (a.text or "x") .. ") (by value); pointcalc does not"
            .. " pass FUNCTION arguments by reference", e.line)
        end
      end
      return proc.lua .. "(" .. call_args(proc, e.args, e.line) .. ")", 20
    elseif k == "fncall" then
      local proc = fn_by_name[e.name]
      if not proc then qerr("Function not defined", e.line) end
      if #e.args ~= #proc.params then qerr("Argument-count mismatch", e.line) end
      local t = {}
      for i, a in ipairs(e.args) do
        local p = proc.params[i]
        if (p.ty == "string") ~= (a.ty == "string") then qerr("Type mismatch", e.line) end
        t[i] = convert(a, p.ty)
      end
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
  -- operands of comparisons: single literals stand for their SINGLE value
  local function rel_operand(e)
    return (emit_value(e, 4, true))
  end

  -- a Lua condition (boolean) for QBasic's "nonzero is true"
  emit_cond = function(e, min)
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
    if k == "var" or k == "index" or k == "result" then return e.ty == "single" or e.ty == "int" end
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
    if e.k == "var" or e.k == "index" or e.k == "result" or e.k == "ucall" or e.k == "fncall" then
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

  convert = function(e, ty)
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
          or ((s.k == "var" or s.k == "index") and s.ty == "long") then
        return (emit_value(e, 0))
      end
      return "clng(" .. emit_value(e, 0) .. ")"
    end
    error("bad type " .. tostring(ty))
  end

  local function lvalue_code(t)
    if t.k == "var" then return lua_name(t)
    elseif t.k == "index" then return emit_index(t)
    elseif t.k == "result" then return t.proc.result end
    error("bad lvalue")
  end

  -- ---- statements ---------------------------------------------------------------------------
  local cur_proc = nil      -- procedure being emitted (nil: main)
  local cur_region = nil    -- GOSUB subroutine being emitted
  local loops = {}          -- open loops: {kind=, exit_label=, used=}
  local exit_count = 0
  local uses_stop = false

  local emit_block, emit_stmt

  local function copy_out(proc)
    local t = {}
    for i, p in ipairs(proc.params) do
      if proc.modified[i] and not p.array then t[#t + 1] = p.lua end
    end
    return table.concat(t, ", ")
  end

  local function exit_loop(line, kind)
    -- find the innermost loop of this kind
    for i = #loops, 1, -1 do
      local l = loops[i]
      if l.kind == kind then
        if i == #loops then return "break" end
        if not l.exit_label then exit_count = exit_count + 1; l.exit_label = "exit_" .. exit_count end
        gotos[#gotos + 1] = { label = "\0" .. l.exit_label, path = copy_path(), line = line, synthetic = true }
        return "goto " .. l.exit_label
      end
      if l.kind == "fn" then break end
    end
    qerr(kind == "for" and "EXIT FOR not within FOR...NEXT" or "EXIT DO not within DO...LOOP", line)
  end

  local function coords(p)
    return emit_value(p.x, 0), emit_value(p.y, 0)
  end

  local function trim_nils(args)
    while #args > 0 and args[#args] == "nil" do args[#args] = nil end
    return table.concat(args, ", ")
  end

  local function opt(e) if e then return (emit_value(e, 0)) end return "nil" end

  local function emit_gfx(st)
    local line = st.line
    local k = st.k
    if k == "pset" or k == "preset" then
      local col = opt(st.color)
      if st.p.step then
        E(line, "do local _x, _y = step_xy(" .. table.concat({ coords(st.p) }, ", ") .. ") "
          .. k .. "(" .. trim_nils({ "_x", "_y", col }) .. ") end")
      else
        local x, y = coords(st.p)
        E(line, k .. "(" .. trim_nils({ x, y, col }) .. ")")
      end
    elseif k == "line" then
      local col = opt(st.color)
      local style = st.style and ('"' .. st.style .. '"') or "nil"
      if st.pattern then
        -- LINE ..., c, [B], &HAAAA: the style bits go after the box flag
        style = (st.style and ('"' .. st.style .. '"') or "nil") .. ", " .. emit_value(st.pattern, 0)
      end
      if not st.p1 then
        if st.p2.step then
          E(line, "do local _x, _y = step_xy(" .. table.concat({ coords(st.p2) }, ", ") .. ") "
            .. "line_to(" .. trim_nils({ "_x", "_y", col, style }) .. ") end")
        else
          local x, y = coords(st.p2)
          E(line, "line_to(" .. trim_nils({ x, y, col, style }) .. ")")
        end
      elseif st.p1.step or st.p2.step then
        local pre = {}
        local x1, y1, x2, y2 = "_x1", "_y1"
        if st.p1.step then
          pre[#pre + 1] = "local _x1, _y1 = step_xy(" .. table.concat({ coords(st.p1) }, ", ") .. ")"
        else
          local a, b = coords(st.p1)
          pre[#pre + 1] = "local _x1, _y1 = " .. a .. ", " .. b
        end
        if st.p2.step then
          -- the second STEP is relative to the first point
          x2 = "_x1 + " .. emit_value(st.p2.x, 11)
          y2 = "_y1 + " .. emit_value(st.p2.y, 11)
        else
          x2, y2 = coords(st.p2)
        end
        E(line, "do " .. table.concat(pre, " ") .. " line(" .. trim_nils({ x1, y1, x2, y2, col, style })
          .. ") end")
      else
        local x1, y1 = coords(st.p1)
        local x2, y2 = coords(st.p2)
        E(line, "line(" .. trim_nils({ x1, y1, x2, y2, col, style }) .. ")")
      end
    elseif k == "circle" then
      local rest = { opt(st.r), opt(st.color), opt(st.a0), opt(st.a1), opt(st.aspect) }
      if st.p.step then
        E(line, "do local _x, _y = step_xy(" .. table.concat({ coords(st.p) }, ", ") .. ") circle("
          .. trim_nils({ "_x", "_y", table.unpack(rest) }) .. ") end")
      else
        local x, y = coords(st.p)
        E(line, "circle(" .. trim_nils({ x, y, table.unpack(rest) }) .. ")")
      end
    elseif k == "paint" then
      local rest = { opt(st.color), opt(st.border) }
      if st.p.step then
        E(line, "do local _x, _y = step_xy(" .. table.concat({ coords(st.p) }, ", ") .. ") paint("
          .. trim_nils({ "_x", "_y", table.unpack(rest) }) .. ") end")
      else
        local x, y = coords(st.p)
        E(line, "paint(" .. trim_nils({ x, y, table.unpack(rest) }) .. ")")
      end
    elseif k == "window" or k == "view" then
      if not st.p1 then E(line, k .. "()"); return end
      local x1, y1 = coords(st.p1)
      local x2, y2 = coords(st.p2)
      local args = { x1, y1, x2, y2 }
      if k == "view" then args[5] = opt(st.fill); args[6] = opt(st.border) end
      if st.screen then args[#args + 1] = '"screen"' end
      E(line, k .. "(" .. trim_nils(args) .. ")")
    elseif k == "screen" then
      E(line, "screen(" .. emit_value(st.mode, 0) .. ")")
    elseif k == "cls" then
      E(line, "cls(" .. (st.arg and emit_value(st.arg, 0) or "") .. ")")
    elseif k == "color" then
      E(line, "color(" .. trim_nils({ opt(st.fg), opt(st.bg) }) .. ")")
    elseif k == "palette" then
      if not st.attr then E(line, "palette()") return end
      E(line, "palette(" .. emit_value(st.attr, 0) .. ", " .. emit_value(st.color, 0) .. ")")
    end
  end

  -- a statement the runtime carries out: helper(args), the left-out ones nil
  local function emit_rtcall(st)
    local args = {}
    for i = 1, st.nargs do args[i] = opt(st.args[i]) end
    E(st.line, st.fn .. "(" .. trim_nils(args) .. ")")
  end

  -- GET (x1, y1)-(x2, y2), a(i) and PUT (x, y), a(i), action: the block is kept beside the
  -- array, at the element named (QBasic stores it in the array's memory)
  local function emit_getput(st)
    local idx = {}
    for i, a in ipairs(st.index) do idx[i] = emit_value(a, 0) end
    local at = "{" .. table.concat(idx, ", ") .. "}"
    local function point(p, base)
      local x, y = coords(p)
      if p.step then
        if base then return base .. "x + " .. x, base .. "y + " .. y end
        return nil, nil, "local _sx, _sy = step_xy(" .. x .. ", " .. y .. ")"
      end
      return x, y
    end
    local pre = {}
    local x1, y1, code = point(st.p1)
    if code then pre[#pre + 1] = code; x1, y1 = "_sx", "_sy" end
    if st.get then
      local x2, y2 = coords(st.p2)
      if st.p2.step then x2, y2 = x1 .. " + " .. x2, y1 .. " + " .. y2 end
      local elem = ({ int = 2, long = 4, single = 4, double = 8 })[st.array.ty]
      E(st.line, "do " .. table.concat(pre, " ") .. " get_into(" .. table.concat({ x1, y1, x2, y2,
        lua_name(st.array), at, elem }, ", ") .. ") end")
    else
      E(st.line, "do " .. table.concat(pre, " ") .. " put_from(" .. table.concat({ x1, y1,
        lua_name(st.array), at, lua_string(st.action) }, ", ") .. ") end")
    end
  end

  -- INPUT and LINE INPUT: the runtime reads the line and gives back the fields, each stored
  -- with its type's rounding as READ does
  local function emit_input(st)
    local kinds = {}
    for i, t in ipairs(st.targets) do kinds[i] = lua_string(t.ty == "string" and "s" or "n") end
    local prompt = st.prompt and lua_string(st.prompt) or "nil"
    local call
    if st.line_input then
      call = "line_input(" .. prompt .. ", " .. tostring(st.same_line or false) .. ")"
    else
      call = "input_fields(" .. prompt .. ", " .. tostring(st.mark) .. ", "
        .. tostring(st.same_line or false) .. ", {" .. table.concat(kinds, ", ") .. "})"
    end
    local parts = { "do local _in = " .. call }
    for i, t in ipairs(st.targets) do
      local v = "_in[" .. i .. "]"
      local code
      if t.ty == "string" or t.ty == "double" then code = v
      elseif t.ty == "single" then code = "csng(" .. v .. ")"
      elseif t.ty == "int" then code = "cint(" .. v .. ")"
      else code = "clng(" .. v .. ")" end
      parts[#parts + 1] = lvalue_code(t) .. " = " .. code
    end
    E(st.line, table.concat(parts, " ") .. " end")
  end

  local function emit_print(st)
    local args = {}
    for _, it in ipairs(st.items) do
      if it.k == "expr" then
        local e = it.e
        if e.ty == "double" then args[#args + 1] = "dbl(" .. emit_value(e, 0, true) .. ")"
        elseif e.ty == "long" then args[#args + 1] = "lng(" .. emit_value(e, 0) .. ")"
        else args[#args + 1] = (emit_value(e, 0)) end
      elseif it.k == "sep" then
        if it.v == "," then args[#args + 1] = "zone" end
      elseif it.k == "tab" or it.k == "spc" then
        args[#args + 1] = it.k .. "(" .. emit_value(it.e, 0) .. ")"
      end
    end
    if not st.newline then args[#args + 1] = "nonl" end
    E(st.line, "qprint(" .. table.concat(args, ", ") .. ")")
  end

  local function emit_call(st)
    local proc = proc_by_name[st.name]
    if not proc or proc.kind ~= "sub" then qerr("Subprogram not defined", st.line) end
    local args = call_args(proc, st.args, st.line)
    local targets, any = {}, false
    for i, p in ipairs(proc.params) do
      if proc.modified[i] and not p.array then
        local a = st.args[i]
        if (a.k == "var" and not a.const) or a.k == "index" then
          targets[#targets + 1] = lvalue_code(a)
          any = true
        else
          targets[#targets + 1] = "_"
        end
      end
    end
    while targets[#targets] == "_" do targets[#targets] = nil end
    if any then
      E(st.line, table.concat(targets, ", ") .. " = " .. proc.lua .. "(" .. args .. ")")
    else
      E(st.line, proc.lua .. "(" .. args .. ")")
    end
  end

  -- the value of a numeric literal, possibly negated, or nil
  local function literal_num(e)
    e = strip(e)
    if e.k == "num" then return e.v, e end
    if e.k == "neg" then
      local a = strip(e.a)
      if a.k == "num" then return -a.v, a end
    end
  end
  -- can this literal be written as is for a value of type ty?
  local function literal_fits(v, lit, ty)
    if ty == "single" then return f32(v) == v end
    if ty == "double" then return lit.ty == "double" or f32(v) == v end
    return v == math.floor(v)
  end

  local function emit_for(node)
    local line = node.line
    local v = node.var
    local vcode = lua_name(v)
    local ty = v.ty
    local decl_names, decl_vals = {}, {}
    -- the limit and the step are evaluated once, rounded to the variable's type
    local lim_code
    local lv, llit = literal_num(node.to)
    if lv and literal_fits(lv, llit, ty) then
      lim_code = emit_value(node.to, 0)
    else
      decl_names[#decl_names + 1] = "_to"
      decl_vals[#decl_vals + 1] = convert(node.to, ty)
      lim_code = "_to"
    end
    local step, step_sign
    if not node.step then
      step, step_sign = "1", 1
    else
      local sv, slit = literal_num(node.step)
      if sv then step_sign = sv >= 0 and 1 or -1 end
      if sv and literal_fits(sv, slit, ty) then
        step = emit_value(node.step, 0)
      else
        decl_names[#decl_names + 1] = "_step"
        decl_vals[#decl_vals + 1] = convert(node.step, ty)
        step = "_step"
      end
    end
    local cond
    if step_sign == 1 then cond = vcode .. " <= " .. lim_code
    elseif step_sign == -1 then cond = vcode .. " >= " .. lim_code
    else cond = "for_test(" .. vcode .. ", " .. lim_code .. ", " .. step .. ")" end
    local head = ""
    if #decl_names > 0 then
      head = "do local " .. table.concat(decl_names, ", ") .. " = " .. table.concat(decl_vals, ", ") .. " "
    end
    E(line, head .. vcode .. " = " .. convert(node.from, ty) .. " while " .. cond .. " do")
    open_block()
    loops[#loops + 1] = { kind = "for" }
    emit_block(node.body)
    local lp = table.remove(loops)
    local incr
    local sum = vcode .. " + " .. step
    if step:sub(1, 1) == "-" then sum = vcode .. " - " .. step:sub(2) end
    if ty == "single" then incr = vcode .. " = csng(" .. sum .. ")"
    elseif ty == "double" then incr = vcode .. " = " .. sum
    elseif ty == "int" then incr = vcode .. " = cint(" .. sum .. ")"
    else incr = vcode .. " = clng(" .. sum .. ")" end
    close_block()
    local tail = incr .. " end"
    if lp.exit_label then
      tail = tail .. " ::" .. lp.exit_label .. "::"
      label_at["\0" .. lp.exit_label] = { path = copy_path(), line = node.next_line }
    end
    if #decl_names > 0 then tail = tail .. " end" end
    E(node.next_line, tail)
  end

  local function emit_while(node)
    E(node.line, "while " .. emit_cond(node.cond) .. " do")
    open_block()
    loops[#loops + 1] = { kind = "while" }
    emit_block(node.body)
    table.remove(loops)
    close_block()
    E(node.end_line, "end")
  end

  local function emit_do(node)
    local top, bottom = node.cond_top, node.cond_bottom
    if bottom then
      E(node.line, "repeat")
    elseif top then
      local c = top.kind == "while" and emit_cond(top.e) or ("not " .. emit_cond(top.e, 12))
      E(node.line, "while " .. c .. " do")
    else
      E(node.line, "while true do")
    end
    open_block()
    loops[#loops + 1] = { kind = "do" }
    emit_block(node.body)
    local lp = table.remove(loops)
    close_block()
    local tail
    if bottom then
      tail = "until " .. (bottom.kind == "until" and emit_cond(bottom.e) or ("not " .. emit_cond(bottom.e, 12)))
    else
      tail = "end"
    end
    if lp.exit_label then
      tail = tail .. " ::" .. lp.exit_label .. "::"
      label_at["\0" .. lp.exit_label] = { path = copy_path(), line = node.end_line }
    end
    E(node.end_line, tail)
  end

  local function emit_ifb(node)
    for i, br in ipairs(node.branches) do
      E(br.line, (i == 1 and "if " or "elseif ") .. emit_cond(br.cond) .. " then")
      open_block()
      emit_block(br.body)
      close_block()
    end
    if node.else_body then
      E(node.else_line, "else")
      open_block()
      emit_block(node.else_body)
      close_block()
    end
    E(node.end_line, "end")
  end

  local function case_test(t, sel_ty)
    local function rhs(e)
      if (sel_ty == "string") ~= (e.ty == "string") then qerr("Type mismatch", t.line) end
      return emit_value(e, 4, true)
    end
    if t.lo then
      return "case >= " .. rhs(t.lo) .. " and case <= " .. rhs(t.hi)
    end
    return "case " .. RELOP_LUA[t.op] .. " " .. rhs(t.e)
  end

  local function emit_select(node)
    local sel = node.expr
    local ty = sel.ty
    local selcode = ty == "string" and emit_value(sel, 0) or convert(sel, ty == "double" and "double" or
      (ty == "int" or ty == "long") and ty or "single")
    E(node.line, "do local case = " .. selcode)
    local first = true
    for _, c in ipairs(node.cases) do
      local tests = {}
      for _, t in ipairs(c.tests) do
        t.line = c.line
        local code = case_test(t, ty)
        if #c.tests > 1 and t.lo then code = "(" .. code .. ")" end
        tests[#tests + 1] = code
      end
      E(c.line, (first and "if " or "elseif ") .. table.concat(tests, " or ") .. " then")
      first = false
      open_block()
      emit_block(c.body)
      close_block()
    end
    if node.else_body then
      if first then E(node.else_line, "do") else E(node.else_line, "else") end
      open_block()
      emit_block(node.else_body)
      close_block()
      E(node.end_line, "end end")
    elseif first then
      E(node.end_line, "end")
    else
      E(node.end_line, "end end")
    end
  end

  local function emit_if1(node)
    local line = node.line
    E(line, "if " .. emit_cond(node.cond) .. " then")
    open_block()
    emit_block(node.then_body)
    close_block()
    if node.else_body then
      E(line, "else")
      open_block()
      emit_block(node.else_body)
      close_block()
    end
    E(line, "end")
  end

  local function end_program(line)
    if cur_proc or cur_region then
      uses_stop = true
      return "stop()"
    end
    return "do return end"
  end

  local emit_proc, emit_region

  emit_stmt = function(st)
    local k = st.k
    local line = st.line
    if k == "label" then
      if goto_targets[st.name] then
        E(line, "::" .. label_lua(st.name) .. "::")
        label_at[st.name] = { path = copy_path(), line = line }
      end
    elseif k == "let" then
      E(line, lvalue_code(st.target) .. " = " .. convert(st.expr, st.target.ty))
    elseif k == "print" then
      emit_print(st)
    elseif k == "for" then
      emit_for(st)
    elseif k == "while" then
      emit_while(st)
    elseif k == "do" then
      emit_do(st)
    elseif k == "ifb" then
      emit_ifb(st)
    elseif k == "if1" then
      emit_if1(st)
    elseif k == "select" then
      emit_select(st)
    elseif k == "goto" then
      E(line, emit_goto(line, st.label))
    elseif k == "gosub" then
      E(line, gosub_lua[st.label] .. "()")
    elseif k == "on" then
      local parts = { "do local on = on_index(" .. emit_value(st.expr, 0) .. ")" }
      for i, l in ipairs(st.labels) do
        local act = st.gosub and (gosub_lua[l] .. "()") or emit_goto(line, l)
        parts[#parts + 1] = (i == 1 and "if" or "elseif") .. " on == " .. i .. " then " .. act
      end
      parts[#parts + 1] = "end end"
      E(line, table.concat(parts, " "))
    elseif k == "return" then
      if cur_region and #path == cur_region.depth then
        -- (never reached: a top-level RETURN ends the subroutine)
        E(line, "do return end")
      elseif cur_region then
        E(line, "do return end")
      else
        E(line, "return_without_gosub()")
      end
    elseif k == "end" then
      E(line, end_program(line))
    elseif k == "exit" then
      if st.what == "for" or st.what == "do" then
        E(line, exit_loop(line, st.what))
      else
        local p = cur_proc
        if not p or p.kind ~= st.what then
          qerr(st.what == "sub" and "EXIT SUB not within SUB" or st.what == "function"
            and "EXIT FUNCTION not within FUNCTION" or "EXIT DEF not within DEF FN", line)
        end
        local ret = p.kind == "sub" and copy_out(p) or p.result
        E(line, "do return" .. (ret ~= "" and (" " .. ret) or "") .. " end")
      end
    elseif k == "dim" then
      for _, d in ipairs(st.decls) do
        if d.bounds then
          local node = { k = "dimarray", name = d.name, ty = d.ty, text = d.text, proc = cur_proc }
          local bs = {}
          for _, b in ipairs(d.bounds) do
            if b.lo then
              bs[#bs + 1] = "{" .. emit_value(b.lo, 0) .. ", " .. emit_value(b.hi, 0) .. "}"
            elseif st.base == 1 then
              bs[#bs + 1] = "{1, " .. emit_value(b.hi, 0) .. "}"
            else
              bs[#bs + 1] = emit_value(b.hi, 0)
            end
          end
          local f = d.ty == "string" and "dim_str" or "dim"
          E(line, lua_name(node) .. " = " .. f .. "(" .. table.concat(bs, ", ") .. ")")
        end
      end
    elseif k == "const" then
      for _, d in ipairs(st.decls) do
        E(line, const_lua[d.const.name] .. " = " .. convert(d.expr, d.const.ty))
      end
    elseif k == "data" or k == "procdef_end" then
      -- DATA items are collected at the end of the program
    elseif k == "read" then
      for _, t in ipairs(st.targets) do
        local src = t.ty == "string" and "read_string()" or "read_number()"
        local code
        if t.ty == "string" or t.ty == "double" then code = src
        elseif t.ty == "single" then code = "csng(" .. src .. ")"
        elseif t.ty == "int" then code = "cint(" .. src .. ")"
        else code = "clng(" .. src .. ")" end
        E(line, lvalue_code(t) .. " = " .. code)
      end
    elseif k == "restore" then
      if st.label then
        if not prog.labels[st.label] then qerr("Label not defined", line) end
        E(line, "restore(" .. lua_string(st.label) .. ")")
      else
        E(line, "restore()")
      end
    elseif k == "call" then
      emit_call(st)
    elseif k == "randomize" then
      E(line, "randomize(" .. emit_value(st.expr, 0) .. ")")
    elseif k == "swap" then
      local a, b = lvalue_code(st.a), lvalue_code(st.b)
      E(line, a .. ", " .. b .. " = " .. b .. ", " .. a)
    elseif k == "procdef" then
      emit_proc(st)
    elseif k == "region" then
      emit_region(st)
    elseif k == "endsub" or k == "endfunction" or k == "enddef" then
      -- handled by emit_proc
    elseif k == "rtcall" then
      emit_rtcall(st)
    elseif k == "getput" then
      emit_getput(st)
    elseif k == "input" then
      emit_input(st)
    elseif k == "screen" or k == "cls" or k == "color" or k == "palette" or k == "pset"
        or k == "preset" or k == "line" or k == "circle" or k == "paint" or k == "window"
        or k == "view" then
      emit_gfx(st)
    else
      error("cannot emit statement " .. k)
    end
  end

  emit_block = function(list)
    for _, st in ipairs(list) do emit_stmt(st) end
  end

  emit_proc = function(st)
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
    if #names > 180 then qerr("too many variables in one procedure for pointcalc", line) end
    local decl = ""
    if #names > 0 then decl = " local " .. table.concat(names, ", ") .. " = " .. table.concat(vals, ", ") end
    for _, a in ipairs(arrays) do
      if a.dimmed then
        decl = decl .. " local " .. a.lua
      else
        -- an array used without DIM: subscripts OPTION BASE..10 in each dimension
        local dims = {}
        for i = 1, a.rank or 1 do dims[i] = prog.option_base == 1 and "{1, 10}" or "10" end
        decl = decl .. " local " .. a.lua .. " = " .. (a.ty == "string" and "dim_str" or "dim")
          .. "(" .. table.concat(dims, ", ") .. ")"
      end
    end
    local saved_proc, saved_loops = cur_proc, loops
    cur_proc = proc
    loops = { { kind = "fn" } }
    open_block(true)
    if proc.expr then
      E(line, head .. decl .. " return " .. convert(proc.expr, proc.ty) .. " end goto "
        .. st.next_def .. " ::" .. st.skip_label .. "::")
    else
      E(line, head .. decl)
      emit_block(proc.tree)
      local ret = proc.kind == "sub" and copy_out(proc) or proc.result
      E(proc.end_line, (ret ~= "" and ("return " .. ret .. " ") or "") .. "end goto " .. st.next_def
        .. " ::" .. st.skip_label .. "::")
    end
    close_block()
    cur_proc, loops = saved_proc, saved_loops
  end

  emit_region = function(r)
    local line = r.line
    E(line, "goto " .. r.skip_label .. " ::" .. r.def_label .. ":: " .. r.lua .. " = function()")
    local saved_loops = loops
    loops = { { kind = "fn" } }
    cur_region = r
    open_block(true)
    r.depth = #path
    emit_block(r.body)
    close_block()
    cur_region = nil
    loops = saved_loops
    local end_line, tail
    if r.return_line then
      end_line = r.return_line
      tail = "end goto " .. r.next_def .. " ::" .. r.skip_label .. ":: " .. r.lua
        .. "() return_without_gosub()"
    else
      -- runs into the next subroutine
      end_line = r.falls_into.line
      tail = "return " .. r.falls_into.lua .. "() end goto " .. r.next_def .. " ::" .. r.skip_label
        .. ":: " .. r.lua .. "() return_without_gosub()"
    end
    E(end_line, tail)
  end

  -- ---- the program ------------------------------------------------------------------------
  open_block(true)
  loops = { { kind = "fn" } }
  emit_block(main_tree)
  close_block()

  -- check the gotos: the label must enclose the goto, in the same function
  for _, g in ipairs(gotos) do
    local l = label_at[g.label]
    if not l then
      if g.synthetic then error("internal: missing exit label") end
      local def = prog.labels[g.label]
      if not def then qerr("Label not defined", g.line) end
      qerr("GOTO " .. g.label .. ": jumps into a block or procedure (line " .. def.line
        .. "); pointcalc translates GOTO only to a label in the same or an enclosing block", g.line)
    end
    local ok = #l.path <= #g.path
    if ok then
      for i = 1, #l.path do if l.path[i] ~= g.path[i] then ok = false break end end
    end
    if ok then
      for i = #l.path + 1, #g.path do
        if type(g.path[i]) == "string" then ok = false end
      end
    end
    if not ok then
      qerr("GOTO " .. g.label:gsub("%z", "") .. ": jumps into a block or another procedure (line "
        .. l.line .. "); pointcalc translates GOTO only to a label in the same or an enclosing block",
        g.line)
    end
  end

  -- ---- assemble ------------------------------------------------------------------------------
  local info = {}
  -- DATA, by line
  if #prog.data > 0 then
    local by_line, order = {}, {}
    for _, d in ipairs(prog.data) do
      if not by_line[d.line] then by_line[d.line] = {}; order[#order + 1] = d.line end
      local v
      if not d.quoted then
        local ok, tok = pcall(require("qbasic_lex").line, d.text)
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
        elseif num then v = exact_text(num.v)
        else v = lua_string(d.text) end
        -- READ s$ of a number gets its text as written (DATA 007, 1.50): keep the text when
        -- the number's own text differs
        if num and num.v - num.v == 0 and rt.data_text(num.v) ~= d.text then
          v = "{" .. v .. ", " .. lua_string(d.text) .. "}"
        end
      else
        v = lua_string(d.text)
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
    local function scan_restore(list)
      for _, st in ipairs(list) do
        if st.k == "restore" and st.label then used[st.label] = true
        elseif st.k == "if1" then scan_restore(st.then_body); scan_restore(st.else_body or {}) end
      end
    end
    scan_restore(prog.main)
    for _, proc in ipairs(prog.procs) do scan_restore(proc.body) end
    for _, name in ipairs(names) do
      if used[name] then dl[#dl + 1] = "[" .. lua_string(name) .. "] = " .. prog.data_labels[name] end
    end
    if #dl > 0 then info[#info + 1] = "data_labels = {" .. table.concat(dl, ", ") .. "}" end
  end
  -- module strings and arrays (undeclared strings are "", arrays dimension themselves 0..10)
  local strs, arrs = {}, {}
  for _, g in ipairs(global_list) do
    if g.array then
      arrs[#arrs + 1] = g.lua .. " = {" .. (g.rank or 1) .. (g.ty == "string" and ', "string"' or "") .. "}"
    elseif g.ty == "string" then
      strs[#strs + 1] = lua_string(g.lua)
    end
  end
  if #strs > 0 then info[#info + 1] = "strings = {" .. table.concat(strs, ", ") .. "}" end
  if #arrs > 0 then info[#info + 1] = "arrays = {" .. table.concat(arrs, ", ") .. "}" end
  if #arrs > 0 and prog.option_base == 1 then info[#info + 1] = "base = 1" end
  if uses_stop then info[#info + 1] = "stops = true" end

  local prelude = "local _ENV = require(\"qbasic_rt\").new(_ENV, " .. lua_string(chunkname)
    .. ") return run(function()"
  if #defs > 0 then prelude = prelude .. " goto " .. defs[1].def_label .. " ::start::" end
  local result = {}
  for i = 1, #lines do
    local code = table.concat(out[i], " ")
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
