-- The QBasic front end of pointcalc: translate(source, chunkname) -> Lua source text, or nil
-- and a message "chunkname:LINE: message" (QBasic's error names: Syntax error, NEXT without
-- FOR, Type mismatch...).
--
-- The translation keeps every source line on the same Lua line (so runtime errors name the
-- QBasic line) and carries the source line as a comment.  See docs/qbasic.md.
--
-- The passes, each in its own file (the words they share are qbasic_keywords.lua):
--   qbasic_lex      a line -> tokens
--   qbasic_parse    tokens -> the syntax tree (statements: qbasic_parse, expressions:
--                   qbasic_parse_expr, blocks: qbasic_blocks)
--   qbasic_resolve  types and QBasic's checks, in textual order
--   qbasic_scope    where each variable lives, Lua names, SUB parameters copied back
--   qbasic_control  GOSUB subroutines, the definition chain, GOTO/EXIT targets
--   qbasic_emit     Lua source (expressions: qbasic_emit_expr, screen: qbasic_emit_gfx,
--                   blocks and the error trap: qbasic_emit_blocks)
-- and the runtime the translation calls: qbasic_rt, qbasic_screen, qbasic_hw (the emulated
-- VGA ports and memory), qbasic_files.
local parse = require "qbasic_parse"
local resolve = require "qbasic_resolve"
local scope = require "qbasic_scope"
local control = require "qbasic_control"
local emit = require "qbasic_emit"

local M = {}

function M.translate(source, chunkname)
  chunkname = chunkname or "?"
  local function pipeline(dispatch)
    local prog = parse.parse(source)
    resolve.resolve(prog)
    scope.scope(prog)
    control.control(prog, dispatch)
    return emit.emit(prog, chunkname)
  end
  -- a GOTO between a GOSUB subroutine and the rest of the module (or of a procedure), or a
  -- GOSUB into a block: again, with that body's subroutines kept in its code (qbasic_control)
  local dispatch = { procs = {} }
  local ok, res = pcall(pipeline, dispatch)
  for _ = 1, 100 do
    if ok or type(res) ~= "table" or not res.qb_redo then break end
    if res.proc then dispatch.procs[res.proc] = true else dispatch.module = true end
    ok, res = pcall(pipeline, dispatch)
  end
  if ok then return res end
  if type(res) == "table" and res.qb then
    return nil, string.format("%s:%d: %s", chunkname, res.line or 0, res.msg or "Syntax error")
  end
  -- nesting deeper than the translator's recursion goes (thousands of parentheses)
  if tostring(res):find("stack overflow", 1, true) then
    return nil, string.format("%s: Expression too complex (nested too deeply)", chunkname)
  end
  -- a bug in the translator: say so, with the Lua error
  return nil, string.format("%s: internal error in the QBasic translator: %s", chunkname,
    tostring(res))
end

return M
