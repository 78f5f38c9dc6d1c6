-- QBasic front end, pass 5 (emit): the blocks.  FOR, WHILE, DO, block and single-line IF and
-- SELECT CASE become Lua's loops and ifs, or, when node.flat (a GOTO or GOSUB into the block,
-- or every block of the module under ON ERROR GOTO: qbasic_control), labels and conditional
-- gotos in the code of their function, which a goto can reach.  Also the code that runs under
-- the error trap, and the locals of a function that the lowered blocks keep.
local X = require "qbasic_emit_expr"
local control = require "qbasic_control"

local M = {}

local value, cond, convert, f32, strip = X.value, X.cond, X.convert, X.f32, X.strip
local label_lua = control.label_lua
local emit_block          -- qbasic_emit's (install)
function M.install(f) emit_block = f end

-- EXIT FOR / EXIT DO: break from the innermost Lua loop, else a goto past the loop's end (a
-- lowered loop, node.flat, is no Lua loop: break leaves the Lua loop around it)
local function exit_loop(S, kind)
  for i = #S.loops, 1, -1 do
    local l = S.loops[i]
    if l.kind == kind then
      local inner = true
      for j = i + 1, #S.loops do if not S.loops[j].flat then inner = false end end
      if inner and not l.flat then return "break" end
      if not l.exit_label then S.exit_count = S.exit_count + 1; l.exit_label = "exit_" .. S.exit_count end
      return "goto " .. l.exit_label
    end
    if l.kind == "fn" then break end
  end
  error("internal: EXIT outside its loop")
end

-- A lowered block (node.flat: a GOTO jumps into it, qbasic_control) keeps what it needs
-- across the jump in locals of its function, declared where the function starts; its labels
-- are numbered through the program (fl<n>_...)
local function temp(S)
  S.temp_count = S.temp_count + 1
  if #S.locals >= 100 then
    -- (Lua allows 200 locals in a function: a big program keeps the rest in a table)
    S.locals.table = true
    return "_ft[" .. S.temp_count .. "]"
  end
  local name = "_f" .. S.temp_count
  S.locals[#S.locals + 1] = name
  return name
end
local function flat_id(S)
  S.flat_count = S.flat_count + 1
  return "fl" .. S.flat_count .. "_"
end
-- code run under the error trap (a program with ON ERROR GOTO: qbasic_rt's trap): RESUME label
-- jumps from here (qbasic_control made every RESUME label reachable from the module's
-- statements); block_end: the label past the block whose condition or bounds this code
-- computes, where RESUME NEXT goes on
local function trapped_code(S, body, block_end)
  local code = "trap(function() " .. body .. " end, " .. S.erl .. (block_end and ", true" or "") .. ")"
  local labels = {}
  for l in pairs(S.prog.resume_targets) do labels[#labels + 1] = l end
  if #labels == 0 and not block_end then return code end
  table.sort(labels)
  local t = { "do local _r = " .. code .. " if _r then" }
  if block_end then t[#t + 1] = 'if _r == "next" then goto ' .. block_end .. " end" end
  if not S.cur_region then
    for _, l in ipairs(labels) do
      t[#t + 1] = "if _r == " .. X.lua_string(l) .. " then goto " .. label_lua(l) .. " end"
    end
  end
  t[#t + 1] = "resume_at(_r) end end"
  return table.concat(t, " ")
end
-- in a lowered block: the code that goes to `target` unless the condition c holds (negate:
-- when it holds); under the trap, the condition is computed into a local first
local function skip_unless(S, c, target, block_end, negate)
  if S.trapping and not S.cur_proc then
    if not S.locals.cond then S.locals.cond = temp(S) end
    local t = S.locals.cond
    return trapped_code(S, t .. " = " .. c, block_end) .. " if " .. (negate and "" or "not ")
      .. t .. " then goto " .. target .. " end"
  end
  return "if " .. (negate and "" or "not ") .. "(" .. c .. ") then goto " .. target .. " end"
end
-- in a lowered block: assignments (a FOR's bounds, a SELECT's value), trapped where needed
local function guarded(S, code, block_end)
  if S.trapping and not S.cur_proc then return trapped_code(S, code, block_end) end
  return code
end

-- where the current function declares those locals: a slot filled by assemble
local function locals_slot(S, line)
  S.locals = {}
  S.E(line, S.locals)
end

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

local function emit_for(S, node)
  local line = node.line
  local v = node.var
  local vcode = S.prog.lua_name(v)
  local ty = v.ty
  local decl_names, decl_vals = {}, {}
  -- the limit and the step are evaluated once, rounded to the variable's type
  local lim_code
  local lv, llit = literal_num(node.to)
  if lv and literal_fits(lv, llit, ty) then
    lim_code = value(node.to, 0)
  else
    lim_code = node.flat and temp(S) or "_to"
    decl_names[#decl_names + 1] = lim_code
    decl_vals[#decl_vals + 1] = convert(node.to, ty)
  end
  local step, step_sign
  if not node.step then
    step, step_sign = "1", 1
  else
    local sv, slit = literal_num(node.step)
    if sv then step_sign = sv >= 0 and 1 or -1 end
    if sv and literal_fits(sv, slit, ty) then
      step = value(node.step, 0)
    else
      step = node.flat and temp(S) or "_step"
      decl_names[#decl_names + 1] = step
      decl_vals[#decl_vals + 1] = convert(node.step, ty)
    end
  end
  local cond
  if step_sign == 1 then cond = vcode .. " <= " .. lim_code
  elseif step_sign == -1 then cond = vcode .. " >= " .. lim_code
  else cond = "for_test(" .. vcode .. ", " .. lim_code .. ", " .. step .. ")" end
  local head = ""
  local id
  if node.flat then
    -- lowered: the test at the top label, NEXT adds the step to the variable as it stands
    -- (also after a GOTO into the body) and goes back to the test
    id = flat_id(S)
    local t = {}
    for i, n in ipairs(decl_names) do t[#t + 1] = n .. " = " .. decl_vals[i] end
    t[#t + 1] = vcode .. " = " .. convert(node.from, ty)
    S.E(line, guarded(S, table.concat(t, " "), id .. "end") .. " ::" .. id .. "top:: if not ("
      .. cond .. ") then goto " .. id .. "end end")
  else
    if #decl_names > 0 then
      head = "do local " .. table.concat(decl_names, ", ") .. " = " .. table.concat(decl_vals, ", ") .. " "
    end
    S.E(line, head .. vcode .. " = " .. convert(node.from, ty) .. " while " .. cond .. " do")
  end
  S.loops[#S.loops + 1] = { kind = "for", flat = node.flat }
  emit_block(S, node.body)
  local lp = table.remove(S.loops)
  local incr
  local sum = vcode .. " + " .. step
  if step:sub(1, 1) == "-" then sum = vcode .. " - " .. step:sub(2) end
  if ty == "single" then incr = vcode .. " = csng(" .. sum .. ")"
  elseif ty == "double" then incr = vcode .. " = " .. sum
  elseif ty == "int" then incr = vcode .. " = cint(" .. sum .. ")"
  else incr = vcode .. " = clng(" .. sum .. ")" end
  if node.flat then
    -- a GOTO into the body before the FOR ever ran: QBasic's NEXT has no loop to continue
    local guard = #decl_names > 0 and ("if " .. decl_names[1] .. " == nil then "
      .. "next_without_for() end ") or ""
    local tail = guard .. incr .. " goto " .. id .. "top ::" .. id .. "end::"
    if lp.exit_label then tail = tail .. " ::" .. lp.exit_label .. "::" end
    S.E(node.next_line, tail)
    return
  end
  local tail = incr .. " end"
  if lp.exit_label then
    tail = tail .. " ::" .. lp.exit_label .. "::"
  end
  if #decl_names > 0 then tail = tail .. " end" end
  S.E(node.next_line, tail)
end

local function emit_while(S, node)
  if node.flat then
    local id = flat_id(S)
    S.E(node.line, "::" .. id .. "top:: " .. skip_unless(S, cond(node.cond), id .. "end", id .. "end"))
    S.loops[#S.loops + 1] = { kind = "while", flat = true }
    emit_block(S, node.body)
    table.remove(S.loops)
    S.E(node.end_line, "goto " .. id .. "top ::" .. id .. "end::")
    return
  end
  S.E(node.line, "while " .. cond(node.cond) .. " do")
  S.loops[#S.loops + 1] = { kind = "while" }
  emit_block(S, node.body)
  table.remove(S.loops)
  S.E(node.end_line, "end")
end

local function emit_do_flat(S, node)
  local top, bottom = node.cond_top, node.cond_bottom
  local id = flat_id(S)
  local head = "::" .. id .. "top::"
  if top then
    head = head .. " " .. skip_unless(S, cond(top.e), id .. "end", id .. "end", top.kind ~= "while")
  end
  S.E(node.line, head)
  S.loops[#S.loops + 1] = { kind = "do", flat = true }
  emit_block(S, node.body)
  local lp = table.remove(S.loops)
  local tail
  if bottom then
    tail = skip_unless(S, cond(bottom.e), id .. "top", id .. "end", bottom.kind ~= "until")
      .. " ::" .. id .. "end::"
  else
    tail = "goto " .. id .. "top ::" .. id .. "end::"
  end
  if lp.exit_label then tail = tail .. " ::" .. lp.exit_label .. "::" end
  S.E(node.end_line, tail)
end

local function emit_do(S, node)
  if node.flat then return emit_do_flat(S, node) end
  local top, bottom = node.cond_top, node.cond_bottom
  if bottom then
    S.E(node.line, "repeat")
  elseif top then
    local c = top.kind == "while" and cond(top.e) or ("not " .. cond(top.e, 12))
    S.E(node.line, "while " .. c .. " do")
  else
    S.E(node.line, "while true do")
  end
  S.loops[#S.loops + 1] = { kind = "do" }
  emit_block(S, node.body)
  local lp = table.remove(S.loops)
  local tail
  if bottom then
    tail = "until " .. (bottom.kind == "until" and cond(bottom.e) or ("not " .. cond(bottom.e, 12)))
  else
    tail = "end"
  end
  if lp.exit_label then
    tail = tail .. " ::" .. lp.exit_label .. "::"
  end
  S.E(node.end_line, tail)
end

-- a lowered IF or SELECT: each branch's test skips to the next one, a branch ends with a
-- goto past the end; tests(i) is the code of branch i's test
local function emit_branches_flat(S, node, branches, tests, else_line)
  local id = flat_id(S)
  for i, br in ipairs(branches) do
    local pre = i > 1 and ("goto " .. id .. "end ::" .. id .. (i - 1) .. ":: ") or ""
    S.E(br.line, pre .. skip_unless(S, tests(i), id .. i, id .. "end"))
    emit_block(S, br.body)
  end
  local n = #branches
  if node.else_body then
    if n > 0 then S.E(else_line, "goto " .. id .. "end ::" .. id .. n .. "::") end
    emit_block(S, node.else_body)
    S.E(node.end_line or node.line, "::" .. id .. "end::")
  else
    S.E(node.end_line or node.line, (n > 0 and ("::" .. id .. n .. ":: ") or "") .. "::" .. id .. "end::")
  end
end

local function emit_ifb(S, node)
  if node.flat then
    return emit_branches_flat(S, node, node.branches,
      function(i) return cond(node.branches[i].cond) end, node.else_line)
  end
  for i, br in ipairs(node.branches) do
    S.E(br.line, (i == 1 and "if " or "elseif ") .. cond(br.cond) .. " then")
    emit_block(S, br.body)
  end
  if node.else_body then
    S.E(node.else_line, "else")
    emit_block(S, node.else_body)
  end
  S.E(node.end_line, "end")
end

local function case_test(t, sel_ty, name)
  name = name or "case"
  local function rhs(e)
    return value(e, 4, true)
  end
  if t.lo then
    return name .. " >= " .. rhs(t.lo) .. " and " .. name .. " <= " .. rhs(t.hi)
  end
  return name .. " " .. X.RELOP_LUA[t.op] .. " " .. rhs(t.e)
end
local function case_tests(c, ty, name)
  local tests = {}
  for _, t in ipairs(c.tests) do
    t.line = c.line
    local code = case_test(t, ty, name)
    if #c.tests > 1 and t.lo then code = "(" .. code .. ")" end
    tests[#tests + 1] = code
  end
  return table.concat(tests, " or ")
end

local function emit_select(S, node)
  local sel = node.expr
  local ty = sel.ty
  local selcode = ty == "string" and value(sel, 0) or convert(sel, ty == "double" and "double" or
    (ty == "int" or ty == "long") and ty or "single")
  if node.flat then
    local tmp = temp(S)
    local id = flat_id(S)
    S.E(node.line, guarded(S, tmp .. " = " .. selcode, id .. "sel"))
    emit_branches_flat(S, node, node.cases,
      function(i) return case_tests(node.cases[i], ty, tmp) end, node.else_line)
    if S.trapping and not S.cur_proc then S.E(node.end_line, "::" .. id .. "sel::") end
    return
  end
  S.E(node.line, "do local case = " .. selcode)
  local first = true
  for _, c in ipairs(node.cases) do
    S.E(c.line, (first and "if " or "elseif ") .. case_tests(c, ty) .. " then")
    first = false
    emit_block(S, c.body)
  end
  if node.else_body then
    if first then S.E(node.else_line, "do") else S.E(node.else_line, "else") end
    emit_block(S, node.else_body)
    S.E(node.end_line, "end end")
  elseif first then
    S.E(node.end_line, "end")
  else
    S.E(node.end_line, "end end")
  end
end

local function emit_if1(S, node)
  local line = node.line
  if node.flat then
    local id = flat_id(S)
    S.E(line, skip_unless(S, cond(node.cond), id .. "else", id .. "end"))
    emit_block(S, node.then_body)
    S.E(line, "goto " .. id .. "end ::" .. id .. "else::")
    if node.else_body then emit_block(S, node.else_body) end
    S.E(line, "::" .. id .. "end::")
    return
  end
  S.E(line, "if " .. cond(node.cond) .. " then")
  emit_block(S, node.then_body)
  if node.else_body then
    S.E(line, "else")
    emit_block(S, node.else_body)
  end
  S.E(line, "end")
end


M.exit_loop, M.temp, M.locals_slot, M.trapped_code = exit_loop, temp, locals_slot, trapped_code
M.emit_for, M.emit_while, M.emit_do = emit_for, emit_while, emit_do
M.emit_ifb, M.emit_if1, M.emit_select = emit_ifb, emit_if1, emit_select

return M
