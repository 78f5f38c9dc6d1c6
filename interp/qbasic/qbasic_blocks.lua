-- QBasic front end, the parser's last step: block structure.  The statements of a body come
-- from the line parser as a flat list (FOR, NEXT, IF-block parts, CASE... are separate
-- statements); build(list) nests them into the syntax tree the later passes walk:
--   for {var, from, to, step, body, next_line}   while {cond, body, end_line}
--   do {cond_top, cond_bottom, body, end_line}   if1 {cond, then_body, else_body}
--   ifb {branches = {{cond, body, line}...}, else_body, else_line, end_line}
--   select {expr, cases = {{tests, body, line}...}, else_body, else_line, end_line}
-- and reports the unmatched ones (NEXT without FOR, Block IF without END IF, ...).
local M = {}

local function qerr(msg, line) error({ qb = true, msg = msg, line = line }, 0) end

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

function M.build(list)
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
      -- (NEXT i% closing FOR i, same name and another type, is the resolve pass's to find)
      if st.var and st.var.name ~= t.node.var.name then qerr("NEXT without FOR", st.line) end
      t.node.next_line = st.line
      t.node.next_var = st.var
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
        then_body = M.build(st.then_body),
        else_body = st.else_body and M.build(st.else_body) }
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

return M
