-- QBasic front end, pass 4: control flow.  GOSUB subroutines (a GOSUB target at the top level
-- of the module becomes a Lua function running to its RETURN: a "region"), the chain of
-- definitions that defines every procedure and subroutine before the program starts, and the
-- checks of GOTO, GOSUB and EXIT targets (Label not defined, a GOTO into another procedure,
-- EXIT FOR outside FOR...NEXT) before anything runs.  A GOTO or RESUME into a block marks the
-- blocks around its label flat (node.flat): qbasic_emit lowers them to labels and gotos.
--
-- control(prog) adds: prog.main and proc.tree (the top level with its regions), gosub_lua
-- (label -> function name) and defs (procdefs and regions in order, with def_label,
-- skip_label and next_def) of the program and of each procedure, prog.goto_targets (labels
-- some GOTO names).
local walk = require "qbasic_walk"

local M = {}

local function qerr(msg, line) error({ qb = true, msg = msg, line = line }, 0) end
-- the module's code needs the GOSUB dispatch (below): translate again with prog.dispatch
local function redo(proc) error({ qb_redo = true, proc = proc and proc.name }, 0) end

-- the Lua label of a QBasic label: L100, L_name
function M.label_lua(name)
  if name:match("^%d+$") then return "L" .. name end
  return "L_" .. name:gsub("%.", "_")
end

-- ---- GOSUB subroutines -------------------------------------------------------------------------
-- The GOSUB targets of a body (the module's, or a procedure's: QBasic's GOSUB stays within its
-- procedure), each the label at the top level of that body where a subroutine starts.
local function gosub_targets_of(list)
  local targets = {}
  walk.stmts(list, function(st)
    if st.k == "gosub" then targets[st.label] = st.line
    elseif st.k == "on" and st.gosub then
      for _, l in ipairs(st.labels) do targets[l] = st.line end
    end
  end)
  return targets
end

-- Split the top level of a body into plain statements and subroutines (regions); returns the
-- new top level.  names: label -> Lua function name; proc: the procedure, nil for the module.
local function split_regions(list, targets, names, proc, handlers, dispatching)
  local regions = {}
  local newtop = {}
  local cur = nil
  for _, st in ipairs(list) do
    if st.k == "label" and targets[st.name] then
      local r = { k = "region", label = st.name, lua = names[st.name], line = st.line,
        body = { st }, proc = proc, handler = handlers and handlers[st.name] ~= nil }
      if cur then cur.falls_into = r end
      cur = r
      regions[#regions + 1] = r
      newtop[#newtop + 1] = r
    elseif cur then
      if st.k == "return" then
        cur.return_line = st.line
        cur = nil
      elseif st.k == "resume" and cur.handler then   -- an error handler ends at its RESUME
        cur.body[#cur.body + 1] = st
        cur.return_line = st.line
        cur = nil
      elseif st.k == "procdef" and st.proc.kind ~= "deffn" then
        -- the SUBs and FUNCTIONs after the module's code: a subroutine without RETURN ends
        -- before them
        cur.open_end, cur.end_line, cur = true, st.line - 1, nil
        newtop[#newtop + 1] = st
      elseif st.k == "procdef" then
        qerr("DEF FN inside a GOSUB subroutine", st.line)
      else
        cur.body[#cur.body + 1] = st
      end
    else
      newtop[#newtop + 1] = st
    end
  end
  -- a subroutine without RETURN runs to the end of the program, which it ends (QBasic checks
  -- RETURN only when it runs)
  if cur then cur.open_end = true end     -- end_line: the program's last line
  -- a GOSUB target inside a block cannot be a subroutine
  for label, line in pairs(targets) do
    local found = false
    for _, r in ipairs(regions) do if r.label == label then found = true end end
    if not found then
      if not dispatching then redo(proc) end
      qerr("GOSUB " .. label .. ": the target must be at the top level of the " ..
        (proc and "procedure" or "program"), line)
    end
  end
  return newtop
end

local function gosub_regions(prog)
  local function names_for(targets, ns, proc)
    local names = {}
    for label, line in pairs(targets) do
      local l = prog.labels[label]
      if not l or l.proc ~= proc then qerr("Label not defined", line) end
      -- through the namespace: a variable gosub.10 (gosub_10 in Lua) gets another name
      names[label] = prog.alloc(ns, { "gosub_" .. label:gsub("%.", "_") })
    end
    return names
  end
  local targets = gosub_targets_of(prog.main)
  -- RETURN line jumps out of its subroutine: only the dispatch mode keeps subroutines in their
  -- body's code, where that jump is a goto
  local function returns_to_line(list)
    local found = false
    walk.stmts(list, function(st) if st.k == "return" and st.label then found = true end end)
    return found
  end
  if not prog.dispatch and returns_to_line(prog.main) then redo() end
  for _, proc in ipairs(prog.procs) do
    if proc.tree and not proc.dispatch and returns_to_line(proc.tree) then redo(proc) end
  end
  -- In dispatch mode (a GOTO between a subroutine and the rest of the module, a GOSUB into a
  -- block) the module's subroutines stay in its code: GOSUB pushes where to come back and
  -- jumps, RETURN pops and jumps back (qbasic_emit), so any GOTO may cross them
  if prog.dispatch then
    for label, line in pairs(targets) do
      local l = prog.labels[label]
      if not l or l.proc then qerr("Label not defined", line) end
    end
    prog.gosub_labels, targets = targets, {}
  end
  -- the error handlers (ON ERROR GOTO label, from anywhere) are subroutines of the module
  local handlers = {}
  local function scan(list)
    walk.stmts(list, function(st)
      if st.k == "onerror" and st.label then
        local l = prog.labels[st.label]
        if not l or l.proc then qerr("Label not defined", st.line) end
        handlers[st.label] = st.line
        targets[st.label] = targets[st.label] or st.line
      end
    end)
  end
  scan(prog.main)
  for _, proc in ipairs(prog.procs) do if proc.tree then scan(proc.tree) end end
  prog.handlers = handlers
  prog.gosub_lua = names_for(targets, prog.gns, nil)
  prog.main = split_regions(prog.main, targets, prog.gosub_lua, nil, handlers, prog.dispatch)
  for _, proc in ipairs(prog.procs) do
    if proc.tree then
      local t = gosub_targets_of(proc.tree)
      if proc.dispatch then      -- as the module's dispatch mode, within the procedure
        names_for(t, proc.ns, proc)
        proc.gosub_labels, t = t, {}
      end
      proc.gosub_lua = names_for(t, proc.ns, proc)
      proc.tree = split_regions(proc.tree, t, proc.gosub_lua, proc, nil, proc.dispatch)
    end
  end
end

-- ---- the definition chain ----------------------------------------------------------------------
-- In a body, every procedure and subroutine is defined before the first statement runs: the
-- body starts with a goto to the first definition, each one jumps to the next, the last to
-- ::start::.
local function chain(list)
  local defs = {}      -- in textual order: procs and regions
  for _, st in ipairs(list) do
    if st.k == "procdef" or st.k == "region" then defs[#defs + 1] = st end
  end
  for _, d in ipairs(defs) do
    local name = d.k == "region" and d.lua or d.proc.lua
    d.def_label = "def_" .. name
    d.skip_label = "skip_" .. name
  end
  for i, d in ipairs(defs) do
    d.next_def = defs[i + 1] and defs[i + 1].def_label or "start"
  end
  return defs
end
local function definition_chain(prog)
  prog.defs = chain(prog.main)
  for _, proc in ipairs(prog.procs) do
    if proc.tree then proc.defs = chain(proc.tree) end
  end
end

-- ---- GOTO and EXIT ----------------------------------------------------------------------------
-- Lua's goto reaches a label in the same block or an enclosing one of the same function: each
-- block gets an id, a function body an id marked "fn"; a GOTO is fine when the label's path of
-- blocks is a prefix of the GOTO's with no function boundary in between.
local function check_jumps(prog)
  local goto_targets = {}
  local function scan(list)
    walk.stmts(list, function(st)
      if st.k == "goto" or (st.k == "return" and st.label) then goto_targets[st.label] = true
      elseif st.k == "on" and not st.gosub then
        for _, l in ipairs(st.labels) do goto_targets[l] = true end
      end
    end)
  end
  scan(prog.main)
  for _, proc in ipairs(prog.procs) do if proc.tree then scan(proc.tree) end end
  prog.goto_targets = goto_targets

  local owner = nil          -- the procedure whose code this is (nil: the module's)
  local block_id = 0
  local trapping = next(prog.handlers) ~= nil
  local path = {}
  local block_node = {}    -- block id -> the statement owning the block (FOR, IF, SELECT...)
  local label_at, gotos = {}, {}
  local loops = {}
  local cur_proc = nil
  local function copy_path() local c = {}; for i, v in ipairs(path) do c[i] = v end; return c end
  local body
  local function inside(list, is_fn, loop, node)
    block_id = block_id + 1
    path[#path + 1] = is_fn and ("fn" .. block_id) or block_id
    block_node[block_id] = node
    -- under ON ERROR GOTO, the module's blocks are lowered so that an error in a condition,
    -- a FOR's bounds or a SELECT's value is trapped where it is computed (qbasic_emit)
    if node and (trapping or prog.dispatch) and not cur_proc and not in_region then
      node.flat = true
    end
    if node and owner and owner.dispatch then node.flat = true end
    if loop then loops[#loops + 1] = loop end
    body(list)
    if loop then loops[#loops] = nil end
    path[#path] = nil
  end
  local in_region = false    -- inside a GOSUB subroutine of a procedure
  local in_sub = false       -- inside any GOSUB subroutine
  local function in_function(list, proc, region, sub)
    local saved_loops, saved_proc, saved_region, saved_sub = loops, cur_proc, in_region, in_sub
    loops, cur_proc, in_region, in_sub = { "fn" }, proc, region, sub
    inside(list, true)
    loops, cur_proc, in_region, in_sub = saved_loops, saved_proc, saved_region, saved_sub
  end
  local function jump(label, line)
    gotos[#gotos + 1] = { label = label, path = copy_path(), line = line, module = not owner,
      owner = owner }
  end
  local function exit(st)
    if st.what == "for" or st.what == "do" then
      for i = #loops, 1, -1 do
        if loops[i] == st.what then return end
        if loops[i] == "fn" then break end
      end
      qerr(st.what == "for" and "EXIT FOR not within FOR...NEXT" or "EXIT DO not within DO...LOOP",
        st.line)
    end
    if in_region then
      -- in dispatch mode the subroutine is in the procedure's code, where EXIT SUB works
      if owner and not owner.dispatch then redo(owner) end
      qerr("EXIT " .. (st.what == "deffn" and "DEF" or st.what:upper()) .. " inside a GOSUB "
        .. "subroutine: not supported by pointcalc", st.line)
    end
    if not cur_proc or cur_proc.kind ~= st.what then
      qerr(st.what == "sub" and "EXIT SUB not within SUB" or st.what == "function"
        and "EXIT FUNCTION not within FUNCTION" or "EXIT DEF not within DEF FN", st.line)
    end
  end
  local STMT = {}
  function STMT.label(st)
    local gl = (owner or prog).gosub_labels
    if goto_targets[st.name] or prog.resume_targets[st.name] or (gl and gl[st.name]) then
      label_at[st.name] = { path = copy_path(), line = st.line }
    end
  end
  STMT["goto"] = function(st) if not st.leaves_handler then jump(st.label, st.line) end end
  local dispatch = prog.dispatch
  local function gosub_jumps()
    return (dispatch and not owner and not in_sub) or (owner and owner.dispatch)
  end
  function STMT.on(st)
    if not st.gosub or gosub_jumps() then
      for _, l in ipairs(st.labels) do jump(l, st.line) end
    end
  end
  function STMT.gosub(st)
    if gosub_jumps() then jump(st.label, st.line) end
  end
  -- RETURN line pops the GOSUB stack and jumps: the dispatch mode's (gosub_regions)
  STMT["return"] = function(st) if st.label then jump(st.label, st.line) end end
  STMT.exit = exit
  STMT["for"] = function(st) inside(st.body, false, "for", st) end
  STMT["while"] = function(st) inside(st.body, false, "while", st) end
  STMT["do"] = function(st) inside(st.body, false, "do", st) end
  function STMT.ifb(st)
    for _, br in ipairs(st.branches) do inside(br.body, false, nil, st) end
    if st.else_body then inside(st.else_body, false, nil, st) end
  end
  function STMT.select(st)
    for _, c in ipairs(st.cases) do inside(c.body, false, nil, st) end
    if st.else_body then inside(st.else_body, false, nil, st) end
  end
  function STMT.if1(st)
    inside(st.then_body, false, nil, st)
    if st.else_body then inside(st.else_body, false, nil, st) end
  end
  function STMT.procdef(st)
    if st.proc.tree then owner = st.proc; in_function(st.proc.tree, st.proc); owner = nil end
  end
  function STMT.region(st) in_function(st.body, nil, st.proc ~= nil, true) end
  -- a statement of the module that can fail jumps to each RESUME label from where it is
  local resume_sites = next(prog.resume_targets) ~= nil
  body = function(list)
    for _, st in ipairs(list) do
      local f = STMT[st.k]
      if f then f(st) end
      if resume_sites and not cur_proc and not in_sub and st.k ~= "label" then
        for l in pairs(prog.resume_targets) do
          gotos[#gotos + 1] = { label = l, path = copy_path(), line = st.line, resume = true }
        end
      end
    end
  end
  in_function(prog.main, nil)

  -- A GOTO into a block of the same function (Lua's goto cannot enter a block): each block
  -- between the label and the part of its path the GOTO shares is lowered to labels and
  -- conditional gotos (node.flat, qbasic_emit), which puts the label in a block the GOTO can
  -- reach.  Lowering a block only removes it from paths, so the jumps that were fine stay so.
  for _, g in ipairs(gotos) do
    local l = label_at[g.label]
    local def = prog.labels[g.label]
    -- a label of another procedure is not defined where the GOTO is (QBasic's labels are local)
    if not def or def.proc ~= g.owner then qerr("Label not defined", g.line) end
    if not l then
      if g.module and not def.proc and not prog.dispatch then redo() end
      if g.owner and not g.owner.dispatch then redo(g.owner) end
      qerr((g.resume and "RESUME " or "GOTO ") .. g.label .. ": jumps into the error handler "
        .. "(line " .. def.line .. "): not supported by pointcalc", g.line)
    end
    local common = 0
    while common < #l.path and common < #g.path and l.path[common + 1] == g.path[common + 1] do
      common = common + 1
    end
    local ok = true
    for i = common + 1, #g.path do if type(g.path[i]) == "string" then ok = false end end
    for i = common + 1, #l.path do if type(l.path[i]) == "string" then ok = false end end
    if not ok and g.module and not prog.labels[g.label].proc and not prog.dispatch then redo() end
    if not ok and g.owner and not g.owner.dispatch then redo(g.owner) end
    if not ok then
      -- (what remains once the dispatch mode keeps the subroutines in their body's code)
      qerr((g.resume and "RESUME " or "GOTO ") .. g.label .. ": jumps into the error handler "
        .. "(line " .. l.line .. "): not supported by pointcalc", g.line)
    end
    for i = common + 1, #l.path do block_node[l.path[i]].flat = true end
  end
end

-- RESUME label: the label must be in the module (each statement that can fail jumps to it,
-- check_jumps)
local function resume_targets(prog)
  prog.resume_targets = {}
  local function scan(list)
    walk.stmts(list, function(st)
      if st.k == "resume" and st.label then
        local l = prog.labels[st.label]
        if not l or l.proc then qerr("Label not defined", st.line) end
        prog.resume_targets[st.label] = true
      end
    end)
  end
  scan(prog.main)
  for _, proc in ipairs(prog.procs) do if proc.tree then scan(proc.tree) end end
  -- a GOTO from an error handler to the module's code outside it leaves the handler as RESUME
  -- label does (st.leaves_handler)
  for _, r in ipairs(prog.main) do
    if r.k == "region" and r.handler then
      local own = {}
      walk.stmts(r.body, function(st) if st.k == "label" then own[st.name] = true end end)
      walk.stmts(r.body, function(st)
        local l = st.k == "goto" and prog.labels[st.label]
        if l and not l.proc and not own[st.label] then
          st.leaves_handler = true
          prog.resume_targets[st.label] = true
        end
      end)
    end
  end
end

function M.control(prog, dispatch)
  dispatch = dispatch or { procs = {} }
  prog.dispatch = dispatch.module
  for _, proc in ipairs(prog.procs) do proc.dispatch = dispatch.procs[proc.name] end
  gosub_regions(prog)
  definition_chain(prog)
  resume_targets(prog)
  check_jumps(prog)
  for l in pairs(prog.resume_targets) do prog.goto_targets[l] = true end
  for l in pairs(prog.gosub_labels or {}) do prog.goto_targets[l] = true end
  for _, proc in ipairs(prog.procs) do
    for l in pairs(proc.gosub_labels or {}) do prog.goto_targets[l] = true end
  end
  -- RESTORE label: the label must exist
  local function restores(list)
    walk.stmts(list, function(st)
      if st.k == "restore" and st.label and not prog.labels[st.label] then
        qerr("Label not defined", st.line)
      end
    end)
  end
  restores(prog.main)
  for _, proc in ipairs(prog.procs) do if proc.tree then restores(proc.tree) end end
  return prog
end

return M
