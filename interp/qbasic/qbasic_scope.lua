-- QBasic front end, pass 3: variables.  Where each variable lives (a module variable is a field
-- of the program's environment, a SUB or FUNCTION variable a Lua local, a parameter, a CONST),
-- the Lua name of every variable, procedure and CONST (kept clear of Lua's words and of the
-- runtime's helpers), the rank of every array (Wrong number of dimensions), and which SUB
-- parameters a SUB changes (they are copied back to the caller's variables).
--
-- scope(prog) adds: prog.lua_name(node), prog.const_lua, prog.globals / global_list,
-- proc.lua, proc.locals / local_list, proc.result, param.lua, proc.modified, prog.alloc and
-- prog.gns (the module's namespace, for the names the next passes make).
local K = require "qbasic_keywords"
local walk = require "qbasic_walk"
local rt = require "qbasic_rt"

local M = {}



local function qerr(msg, line) error({ qb = true, msg = msg, line = line }, 0) end

-- ---- namespaces ------------------------------------------------------------------------------
local function new_ns()
  local ns = {}
  for w in pairs(K.LUA_KEYWORDS) do ns[w] = true end
  for _, w in ipairs(rt.names) do ns[w:lower()] = true end
  return ns
end
local function clean(text, name)
  local t = (text or name):gsub("[%$%%&!#]$", ""):gsub("%.", "_")
  return t
end
-- the first candidate free in ns, else the first with _2, _3...
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
M.alloc = alloc

local function is_array_node(node)
  return node.k == "index" or node.k == "arrayref" or node.k == "dimarray"
end
local function key_of(node)
  local arr = is_array_node(node)
  return (arr and "()" or "") .. node.name .. K.suffix(node.ty), arr
end

function M.scope(prog)
  local gns = new_ns()
  prog.gns, prog.alloc = gns, alloc

  -- procedures, DEF FNs and CONSTs first: they are the program's global functions/values
  for _, proc in ipairs(prog.procs) do proc.lua = alloc(gns, { clean(proc.text, proc.name) }) end
  local const_lua = {}
  local const_list = {}
  for _, c in pairs(prog.consts) do const_list[#const_list + 1] = c end
  table.sort(const_list, function(a, b) return a.line < b.line end)
  for _, c in ipairs(const_list) do const_lua[c.name] = alloc(gns, { clean(c.text, c.name) }) end
  prog.const_lua = const_lua

  -- which variables are module (global) variables, which are procedure locals
  for _, proc in ipairs(prog.procs) do
    proc.paramkeys = {}
    for i, p in ipairs(proc.params) do
      p.key = (p.array and "()" or "") .. p.name .. K.suffix(p.ty)
      p.index = i
      proc.paramkeys[p.key] = p
    end
    proc.locals, proc.local_list, proc.global_refs = {}, {}, {}
  end
  local function is_shared(proc, node)
    local sc = proc.scope.shared
    if is_array_node(node) then
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
    -- STATIC variables keep their values between calls: module variables of their own name
    if proc.static_all or proc.scope.static[(is_array_node(node) and "()" or "") .. node.name] then
      return "static"
    end
    return "local"
  end
  prog.classify = classify
  local function static_key(node) return node.proc.lua .. ":" .. key_of(node) end

  local globals, global_list = {}, {}
  local function note(node, proc)
    local k = node.k
    if k == "dimarray" or k == "dimvar" then
      local d = node.decl
      node = { k = k, name = d.name, ty = d.ty, text = d.text, proc = proc, decl = d }
    elseif k ~= "var" and k ~= "index" and k ~= "arrayref" then
      return
    end
    local class = classify(node)
    if class == "const" or class == "param" then return end
    local key, arr = key_of(node)
    local info
    if class == "global" or class == "static" then
      local text = node.text
      if class == "static" then
        key = static_key(node)
        text = clean(node.proc.text) .. "_" .. node.text
      end
      if node.proc then node.proc.global_refs[key] = true end
      info = globals[key]
      if not info then
        info = { key = key, array = arr, ty = node.ty, text = text, name = node.name,
          rank = nil, dimmed = false, fixed = node.fixed }
        globals[key] = info
        global_list[#global_list + 1] = info
      end
    else
      info = node.proc.locals[key]
      if not info then
        info = { key = key, array = arr, ty = node.ty, text = node.text, name = node.name,
          rank = nil, dimmed = false, fixed = node.fixed }
        node.proc.locals[key] = info
        node.proc.local_list[#node.proc.local_list + 1] = info
      end
    end
    if node.k == "index" and not info.rank then info.rank = #node.args end
    if node.k == "dimarray" then info.dimmed = true; info.rank = info.rank or #node.decl.bounds end
    if node.k == "index" and info.rank ~= #node.args then
      qerr("Wrong number of dimensions", node.line or 0)
    end
  end
  walk.body_exprs(prog.main, function(e) note(e, nil) end)
  for _, proc in ipairs(prog.procs) do
    local function note_here(e) note(e, proc) end
    if proc.expr then walk.expr(proc.expr, note_here) end
    if proc.tree then walk.body_exprs(proc.tree, note_here) end
  end
  prog.globals, prog.global_list = globals, global_list

  -- global variable names: default-looking scalars first, then the others, then arrays
  local function var_cands(info)
    local base = clean(info.text, info.name)
    if info.array then return { base, base .. "_arr" } end
    return { base, base .. "_" .. K.name_letter(info.ty) }
  end
  local function plain(info) return not info.text:match("[%$%%&!#]$") end
  local function name_all(list, ns)
    for pass = 1, 3 do
      for _, info in ipairs(list) do
        local want = (pass == 1 and not info.array and plain(info))
          or (pass == 2 and not info.array and not plain(info)) or (pass == 3 and info.array)
        if want then info.lua = alloc(ns, var_cands(info)) end
      end
    end
  end
  name_all(global_list, gns)
  -- names of procedure locals
  for _, proc in ipairs(prog.procs) do
    local ns = new_ns()
    for _, p in ipairs(prog.procs) do ns[p.lua:lower()] = true end
    for _, l in pairs(const_lua) do ns[l:lower()] = true end
    -- module variables this procedure uses (SHARED, or any for DEF FN) keep their names
    for key in pairs(proc.global_refs) do ns[globals[key].lua:lower()] = true end
    for _, p in ipairs(proc.params) do
      p.lua = alloc(ns, { clean(p.text, p.name), clean(p.text, p.name) .. "_" .. K.name_letter(p.ty) })
    end
    if proc.kind ~= "sub" and not proc.expr then proc.result = alloc(ns, { proc.lua .. "_result" }) end
    name_all(proc.local_list, ns)
    proc.ns = ns       -- for the names of the procedure's GOSUB subroutines (qbasic_control)
    local nscalars = proc.result and 1 or 0
    for _, info in ipairs(proc.local_list) do if not info.array then nscalars = nscalars + 1 end end
    if nscalars > 180 then   -- Lua's limit of 200 locals a function
      qerr("too many variables in one procedure for pointcalc", proc.line)
    end
  end

  function prog.lua_name(node)
    local class, p = classify(node)
    if class == "const" then return const_lua[node.const.name] end
    if class == "param" then return p.lua end
    local key = key_of(node)
    if class == "global" then return globals[key].lua end
    if class == "static" then return globals[static_key(node)].lua end
    return node.proc.locals[key].lua
  end

  M.modified_params(prog, classify)
  return prog
end

-- ---- SUB parameters changed inside (copied back to the caller's variables) -----------------
function M.modified_params(prog, classify)
  local function param_of(proc, node)
    if not proc or node.k ~= "var" or node.const then return nil end
    local class, p = classify(node)
    if class == "param" and node.proc == proc then return p end
  end
  local function each_stmt(proc, fn) if proc.tree then walk.stmts(proc.tree, fn) end end
  for _, proc in ipairs(prog.procs) do
    proc.modified = {}
    local function mark(node) local p = param_of(proc, node); if p then proc.modified[p.index] = true end end
    each_stmt(proc, function(st)
      if st.k == "let" then mark(st.target)
      elseif st.k == "for" then mark(st.var)
      elseif st.k == "read" or st.k == "input" or st.k == "finput" then
        for _, t in ipairs(st.targets) do mark(t) end
      elseif st.k == "justify" then mark(st.target)
      elseif st.k == "frecord" and st.which == "get" and st.var then mark(st.var)
      elseif st.k == "swap" then mark(st.a); mark(st.b) end
    end)
  end
  -- passing a parameter on to a SUB that changes it changes it too
  local changed = true
  while changed do
    changed = false
    for _, proc in ipairs(prog.procs) do
      each_stmt(proc, function(st)
        local callee = st.k == "call" and prog.proc_by_name[st.name]
        if callee then
          for i, a in ipairs(st.args) do
            local p = param_of(proc, a)
            if p and callee.modified[i] and not proc.modified[p.index] then
              proc.modified[p.index] = true
              changed = true
            end
          end
        end
      end)
    end
  end
end

return M
