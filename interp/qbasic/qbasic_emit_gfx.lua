-- QBasic front end, pass 5 (the screen's statements): the Lua of the drawing statements
-- (PSET, LINE, CIRCLE, PAINT, WINDOW, VIEW, COLOR, PALETTE, CLS), the statements the runtime
-- carries out as calls (SCREEN, LOCATE, DRAW, SOUND...), GET/PUT, INPUT and PRINT.  Each
-- function emits one statement through E(line, code) (install).
local X = require "qbasic_emit_expr"

local M = {}

local prog, E
local value = X.value
function M.install(p, emit_line) prog, E = p, emit_line end

local function coords(p)
  return value(p.x, 0), value(p.y, 0)
end

local function trim_nils(args)
  while #args > 0 and args[#args] == "nil" do args[#args] = nil end
  return table.concat(args, ", ")
end

local function opt(e) if e then return (value(e, 0)) end return "nil" end

function M.gfx(st)
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
      style = (st.style and ('"' .. st.style .. '"') or "nil") .. ", " .. value(st.pattern, 0)
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
        x2 = "_x1 + " .. value(st.p2.x, 11)
        y2 = "_y1 + " .. value(st.p2.y, 11)
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
    E(line, "screen(" .. value(st.mode, 0) .. ")")
  elseif k == "cls" then
    E(line, "cls(" .. (st.arg and value(st.arg, 0) or "") .. ")")
  elseif k == "color" then
    E(line, "color(" .. trim_nils({ opt(st.fg), opt(st.bg), opt(st.border) }) .. ")")
  elseif k == "palette" then
    if not st.attr then E(line, "palette()") return end
    E(line, "palette(" .. value(st.attr, 0) .. ", " .. value(st.color, 0) .. ")")
  end
end

-- a statement the runtime carries out: helper(args), the left-out ones nil
function M.rtcall(st)
  local args = {}
  for i = 1, st.nargs do args[i] = opt(st.args[i]) end
  E(st.line, st.fn .. "(" .. trim_nils(args) .. ")")
end

-- GET (x1, y1)-(x2, y2), a(i) and PUT (x, y), a(i), action: the block is kept beside the
-- array, at the element named (QBasic stores it in the array's memory)
function M.getput(st)
  local idx = {}
  for i, a in ipairs(st.index) do idx[i] = value(a, 0) end
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
      prog.lua_name(st.array), at, elem }, ", ") .. ") end")
  else
    E(st.line, "do " .. table.concat(pre, " ") .. " put_from(" .. table.concat({ x1, y1,
      prog.lua_name(st.array), at, X.lua_string(st.action) }, ", ") .. ") end")
  end
end

-- INPUT and LINE INPUT: the runtime reads the line and gives back the fields, each stored
-- with its type's rounding as READ does
function M.input(st)
  local kinds = {}
  for i, t in ipairs(st.targets) do kinds[i] = X.lua_string(t.ty == "string" and "s" or "n") end
  local prompt = st.prompt and X.lua_string(st.prompt) or "nil"
  local call
  if st.file then         -- INPUT #n, LINE INPUT #n: the fields of the file
    local n = value(st.file, 0)
    call = st.line_input and ("flineinput(" .. n .. ")")
      or ("finput(" .. n .. ", {" .. table.concat(kinds, ", ") .. "})")
  elseif st.line_input then
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
    if t.fixed then code = "fixstr(" .. code .. ", " .. t.fixed .. ")" end
    parts[#parts + 1] = X.lvalue(t) .. " = " .. code
  end
  E(st.line, table.concat(parts, " ") .. " end")
end

-- PRINT's items: QBasic prints them one by one, so an item that fails (trapped, RESUME NEXT)
-- leaves the items before it printed.  In a program with an error handler a PRINT of several
-- items is one call per item (with the separators before it), the last call ending the line
-- unless the PRINT does not; elsewhere one call (the items evaluated first: docs/qbasic.md).
function M.print(st)
  local calls, args = {}, {}
  for _, it in ipairs(st.items) do
    if it.k == "expr" then
      local e = it.e
      if e.ty == "double" then args[#args + 1] = "dbl(" .. value(e, 0, true) .. ")"
      elseif e.ty == "long" then args[#args + 1] = "lng(" .. value(e, 0) .. ")"
      else args[#args + 1] = (value(e, 0)) end
    elseif it.k == "sep" then
      if it.v == "," then args[#args + 1] = "zone" end
    elseif it.k == "tab" or it.k == "spc" then
      args[#args + 1] = it.k .. "(" .. value(it.e, 0) .. ")"
    end
    if it.k ~= "sep" then calls[#calls + 1], args = args, {} end
  end
  if #args > 0 or #calls == 0 then calls[#calls + 1] = args end   -- trailing commas: zones
  if not next(prog.handlers or {}) then   -- no error trap: one call
    local all = {}
    for _, c in ipairs(calls) do for _, a in ipairs(c) do all[#all + 1] = a end end
    calls = { all }
  end
  if not st.newline then local last = calls[#calls] last[#last + 1] = "nonl" end
  local fn = st.file and "fprint(" or "qprint("   -- PRINT #n: the same items into the file
  local code = {}
  for i, c in ipairs(calls) do
    if i < #calls then c[#c + 1] = "nonl" end
    if st.file then table.insert(c, 1, #calls == 1 and (value(st.file, 0)) or "_pf") end
    code[#code + 1] = fn .. table.concat(c, ", ") .. ")"
  end
  if #code == 1 then E(st.line, code[1]) return end
  local file = st.file and ("local _pf = " .. value(st.file, 0) .. " ") or ""
  E(st.line, "do " .. file .. table.concat(code, " ") .. " end")
end

-- PRINT USING: the runtime formats the values (qbasic_using.lua)
function M.print_using(st)
  local args = { (value(st.format, 0)) }
  for _, v in ipairs(st.values) do
    if v.ty == "double" then args[#args + 1] = "dbl(" .. value(v, 0, true) .. ")"
    else args[#args + 1] = (value(v, 0)) end
  end
  if not st.newline then args[#args + 1] = "nonl" end
  if st.file then   -- PRINT #n, USING: into the file
    table.insert(args, 1, (value(st.file, 0)))
    E(st.line, "fprint_using(" .. table.concat(args, ", ") .. ")")
    return
  end
  E(st.line, "qprint_using(" .. table.concat(args, ", ") .. ")")
end

return M
