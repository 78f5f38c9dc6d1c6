-- The QBasic front end of pointcalc: translate(source, chunkname) -> Lua source text, or nil
-- and a message "chunkname:LINE: message" (QBasic's error names: Syntax error, NEXT without
-- FOR, Type mismatch...).
--
-- The translation keeps every source line on the same Lua line (so runtime errors name the
-- QBasic line) and carries the source line as a comment.  See docs/qbasic.md.
local parse = require "qbasic_parse"
local gen = require "qbasic_gen"

local M = {}

function M.translate(source, chunkname)
  chunkname = chunkname or "?"
  local ok, res = pcall(function()
    local prog = parse.parse(source)
    return gen.generate(prog, chunkname)
  end)
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
