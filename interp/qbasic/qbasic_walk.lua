-- QBasic front end: visiting the syntax tree, in the program's textual order.
--   expr(e, fn)            fn(node) for e and every expression inside it
--   stmt_exprs(st, fn)     fn for every expression (and variable) of one statement, without
--                          its nested statements; DIM gives {k="dimarray"|"dimvar", decl}
--   stmts(list, fn)        fn(st) for every statement of a body and of the bodies nested in
--                          it (loops, IF, SELECT, single-line IF), not into procedures
local M = {}

local function expr(e, fn)
  if not e then return end
  fn(e)
  local k = e.k
  if k == "bin" or k == "rel" or k == "logic" then expr(e.a, fn); expr(e.b, fn)
  elseif k == "neg" or k == "not" or k == "paren" then expr(e.a, fn)
  elseif k == "field" then expr(e.base, fn)
  elseif k == "index" or k == "call" or k == "ucall" or k == "fncall" then
    for _, a in ipairs(e.args) do expr(a, fn) end
  end
end
M.expr = expr

-- the expressions of each statement kind, in the order they are written
local EXPRS = {}
local function coords(p, x) if p then x(p.x); x(p.y) end end
function EXPRS.let(st, x) x(st.target); x(st.expr) end
function EXPRS.print(st, x) x(st.file); for _, it in ipairs(st.items) do x(it.e) end end
function EXPRS.dim(st, x, fn)
  for _, d in ipairs(st.decls) do
    fn({ k = d.bounds and "dimarray" or "dimvar", decl = d })
    for _, b in ipairs(d.bounds or {}) do x(b.lo); x(b.hi) end
  end
end
EXPRS.static = EXPRS.dim
function EXPRS.const(st, x) for _, d in ipairs(st.decls) do x(d.expr) end end
function EXPRS.read(st, x) for _, t in ipairs(st.targets) do x(t) end end
EXPRS.input = EXPRS.read
EXPRS["for"] = function(st, x) x(st.var); x(st.from); x(st.to); x(st.step) end
function EXPRS.if1(st, x) x(st.cond) end
EXPRS["while"] = EXPRS.if1
function EXPRS.midset(st, x) x(st.target); x(st.start); x(st.len); x(st.expr) end
function EXPRS.print_using(st, x)
  x(st.file); x(st.format)
  for _, v in ipairs(st.values) do x(v) end
end
function EXPRS.erase(st, x, fn) for _, a in ipairs(st.arrays) do fn(a) end end
function EXPRS.select(st, x) x(st.expr) end
EXPRS.on, EXPRS.randomize = EXPRS.select, EXPRS.select
function EXPRS.call(st, x) for _, a in ipairs(st.args) do x(a) end end
function EXPRS.cls(st, x) x(st.arg) end
function EXPRS.color(st, x) x(st.fg); x(st.bg); x(st.border) end
function EXPRS.palette(st, x) x(st.attr); x(st.color) end
function EXPRS.pset(st, x) coords(st.p, x); x(st.color) end
EXPRS.preset = EXPRS.pset
function EXPRS.line(st, x) coords(st.p1, x); coords(st.p2, x); x(st.color); x(st.pattern) end
function EXPRS.circle(st, x)
  coords(st.p, x); x(st.r); x(st.color); x(st.a0); x(st.a1); x(st.aspect)
end
function EXPRS.paint(st, x) coords(st.p, x); x(st.color); x(st.border) end
function EXPRS.window(st, x) coords(st.p1, x); coords(st.p2, x); x(st.fill); x(st.border) end
EXPRS.view = EXPRS.window
function EXPRS.swap(st, x) x(st.a); x(st.b) end
function EXPRS.rtcall(st, x) for i = 1, st.nargs do x(st.args[i]) end end
function EXPRS.justify(st, x) x(st.target); x(st.expr) end
function EXPRS.common(st, x, fn)
  for _, item in ipairs(st.items) do
    if item.array then fn(item.node) else x(item.node) end
  end
end
function EXPRS.palette_using(st, x, fn)
  fn(st.array)
  for _, a in ipairs(st.index) do x(a) end
end
-- files
function EXPRS.finput(st, x) x(st.file); for _, t in ipairs(st.targets) do x(t) end end
function EXPRS.close(st, x) for _, a in ipairs(st.files) do x(a) end end
function EXPRS.write(st, x) x(st.file); for _, v in ipairs(st.values) do x(v) end end
function EXPRS.frecord(st, x) x(st.file); x(st.record); x(st.var) end
function EXPRS.field(st, x) x(st.file); for _, f in ipairs(st.fields) do x(f.width); x(f.var) end end
function EXPRS.getput(st, x, fn)
  coords(st.p1, x); coords(st.p2, x)
  fn(st.array)
  for _, a in ipairs(st.index) do x(a) end
end

function M.stmt_exprs(st, fn)
  local f = EXPRS[st.k]
  if f then f(st, function(e) expr(e, fn) end, fn) end
end

-- every statement, nested ones after the statement that holds them (and a loop's or an IF's
-- conditions in their textual places: stmts gives the node, then its bodies in order)
local function stmts(list, fn, on_part)
  for _, st in ipairs(list) do
    fn(st)
    local k = st.k
    if k == "for" or k == "while" then stmts(st.body, fn, on_part)
    elseif k == "do" then
      stmts(st.body, fn, on_part)
      if on_part and st.cond_bottom then on_part(st.cond_bottom.e) end
    elseif k == "if1" then
      stmts(st.then_body, fn, on_part)
      if st.else_body then stmts(st.else_body, fn, on_part) end
    elseif k == "ifb" then
      for i, br in ipairs(st.branches) do
        if on_part and i > 1 then on_part(br.cond) end
        stmts(br.body, fn, on_part)
      end
      if st.else_body then stmts(st.else_body, fn, on_part) end
    elseif k == "select" then
      for _, c in ipairs(st.cases) do
        if on_part then
          for _, t in ipairs(c.tests) do on_part(t.e); on_part(t.lo); on_part(t.hi) end
        end
        stmts(c.body, fn, on_part)
      end
      if st.else_body then stmts(st.else_body, fn, on_part) end
    elseif k == "region" then
      stmts(st.body, fn, on_part)
    end
  end
end
M.stmts = stmts

-- every expression of a body, nested statements included, in textual order: fn(node)
function M.body_exprs(list, fn)
  stmts(list, function(st)
    if st.k == "ifb" then expr(st.branches[1].cond, fn)
    elseif st.k == "do" then if st.cond_top then expr(st.cond_top.e, fn) end
    else M.stmt_exprs(st, fn) end
  end, function(e) expr(e, fn) end)
end

return M
