-- The Lua side of the REPL (interp/repl.c runs the loop): how values print, the error
-- messages, what Tab completes, and the :commands.  The commands' descriptions live in the help
-- registry (interp/help.lua); native holds the C functions of repl.c (show, save, load, clear,
-- watch, columns), set by init.

local help = require "help"

local M = {}
local native = {}

function M.init(n)
  native = n
end

local function out(...)
  io.stdout:write(...)
end

-- ---- printing values -------------------------------------------------------------------

local MAX_ITEMS = 8      -- elements shown of a table
local MAX_WIDTH = 100    -- characters of a table summary
local MAX_STRING = 40    -- characters of a string inside a summary

-- Names of the functions reachable from the globals (math.sin, qb.rnd, lerp), for printing:
-- the documented name when there is one (a user's alias `f = lerp` still prints as lerp), else
-- the shortest.
local function function_names()
  local names = {}
  local function better(name, old)
    local documented, was = help.by_name[name] ~= nil, help.by_name[old] ~= nil
    if documented ~= was then return documented end
    return #name < #old
  end
  local function scan(t, prefix, depth)
    for k, v in pairs(t) do
      if type(k) == "string" and k:match("^[%a_][%w_]*$") then
        local name = prefix .. k
        if type(v) == "function" then
          if not names[v] or better(name, names[v]) then names[v] = name end
        elseif type(v) == "table" and depth > 0 and v ~= _G and k ~= "package" and k ~= "loaded" then
          scan(v, name .. ".", depth - 1)
        end
      end
    end
  end
  scan(_G, "", 1)
  return names
end

local function has_tostring(v)
  local mt = debug.getmetatable(v)
  return type(mt) == "table" and rawget(mt, "__tostring") ~= nil
end

local function safe_tostring(v)
  local ok, s = pcall(tostring, v)
  if ok and type(s) == "string" then return s end
  return "<" .. type(v) .. ": __tostring failed>"
end

local function describe_function(f)
  local name = function_names()[f]
  local e = name and help.find(name)
  if e then return "function " .. help.forms(e)[1] .. "   (:help " .. name .. ")" end
  local info = debug.getinfo(f, "S")
  if info.what == "C" then return "builtin function" .. (name and " " .. name or "") end
  local where = info.short_src .. ":" .. info.linedefined
  return "function" .. (name and " " .. name or "") .. " (defined at " .. where .. ")"
end

local describe

-- A short form of a value inside a table summary.
local function brief(v)
  local t = type(v)
  if t == "string" then
    if #v > MAX_STRING then v = v:sub(1, MAX_STRING) .. "..." end
    return (string.format("%q", v):gsub("\\\n", "\\n"))
  elseif t == "table" and not has_tostring(v) then
    local n = 0
    for _ in pairs(v) do n = n + 1 end
    return n == 0 and "{}" or "{...}"
  elseif t == "function" then
    local name = function_names()[v]
    return name and ("function " .. name) or "function"
  end
  return safe_tostring(v)
end

local function is_identifier(k)
  return type(k) == "string" and k:match("^[%a_][%w_]*$") ~= nil
end

-- A table: "table: 3 items {1, 2, 3}", never more than MAX_ITEMS elements or MAX_WIDTH chars.
local function describe_table(t)
  local count, n = 0, #t
  for _ in pairs(t) do count = count + 1 end
  local mt = debug.getmetatable(t)
  local name = mt and rawget(mt, "__name")
  local kind = type(name) == "string" and name or "table"
  if mt and rawget(mt, "__call") then kind = kind .. " (callable)" end
  local head = kind .. ": " ..
      (count == 0 and "empty" or count == 1 and "1 item" or count .. " items")
  if count == 0 then return head .. " {}" end
  local limit = math.min(MAX_WIDTH, (native.columns and native.columns() or 80) - 1) - #head - 8
  local parts, width, shown = {}, 0, 0
  local function add(s)
    if shown >= MAX_ITEMS or width + #s > limit then return false end
    parts[#parts + 1] = s
    width = width + #s + 2
    shown = shown + 1
    return true
  end
  local full = true
  for i = 1, n do
    if not add(brief(t[i])) then full = false break end
  end
  if full then
    local keys = {}
    for k in pairs(t) do
      if not (math.type(k) == "integer" and k >= 1 and k <= n) then keys[#keys + 1] = k end
    end
    table.sort(keys, function(a, b)
      if type(a) == type(b) and (type(a) == "string" or type(a) == "number") then return a < b end
      return type(a) < type(b)
    end)
    for _, k in ipairs(keys) do
      local key = is_identifier(k) and k or "[" .. brief(k) .. "]"
      if not add(key .. " = " .. brief(t[k])) then full = false break end
    end
  end
  return head .. " {" .. table.concat(parts, ", ") .. (full and "" or ", ...") .. "}"
end

function describe(v)
  local t = type(v)
  if t == "table" and not has_tostring(v) then return describe_table(v) end
  if t == "function" then return describe_function(v) end
  return safe_tostring(v)
end
M.describe = describe

-- The text printed for a statement's results (nil when there are none).
function M.results(...)
  local n = select("#", ...)
  if n == 0 then return nil end
  local parts = {}
  for i = 1, n do parts[i] = describe((select(i, ...))) end
  return table.concat(parts, "\t")
end

local local_hint_shown = false

-- Called by repl.c after a chunk ran: its source and its results.  Returns the text to print.
function M.after_chunk(src, ...)
  local text = M.results(...)
  local name = not src:find("\n") and src:match("^%s*local%s+function%s+([%a_][%w_]*)")
      or src:match("^%s*local%s+([%a_][%w_]*)")
  if not local_hint_shown and name and not src:find("\n") then
    local_hint_shown = true
    local note = "(note: a local lasts only for its own input line; drop 'local' to keep " ..
        name .. ")"
    text = text and text .. "\n" .. note or note
  end
  return text
end

-- A hint for a misspelt global ("attempt to call a nil value (global 'circel')"): the one
-- suggester of scripts, -e chunks and the REPL (pcl_global_hint in stdlib/lua/pcl_args.c).
local function hint(msg)
  local name = msg:match("a nil value %(global '([%w_]+)'%)")
  if not name then return nil end
  if name == "help" then return "(hint: :help NAME, e.g. :help lerp)" end
  local pc = package.loaded.pointcalc or rawget(_G, "pointcalc")
  local tk = pc and rawget(pc, "_tk")
  return tk and tk.global_hint and tk.global_hint(msg) or nil
end

-- The error handler of every statement: the message, plus the traceback when it says more
-- than "in the main chunk".
function M.on_error(e)
  local msg
  if type(e) == "string" then msg = e
  elseif has_tostring(e) then msg = safe_tostring(e)
  else msg = "(error object is a " .. type(e) .. " value)" end
  local tb = debug.traceback("", 2)
  -- the frames of the user's code: up to the REPL's own machinery, without the chunk typed at
  -- the prompt and the builtins around it
  local lines = {}
  for line in tb:gmatch("[^\n]+") do
    if line:find("[pointcalc/repl.lua]", 1, true) then break end
    if not (line == "stack traceback:" or line:match("^%s*%[C%]: in %?$")
            or line:match("^%s*stdin:%d+: in main chunk$")) then
      lines[#lines + 1] = line
    end
  end
  while #lines > 0 and (lines[#lines]:match("^%s*%[C%]:") or lines[#lines]:match("%(%.%.%.tail calls%.%.%.%)")) do
    lines[#lines] = nil
  end
  if #lines > 0 and lines[1]:match("^%s*%[C%]: in function 'error'$") then table.remove(lines, 1) end
  local h = hint(msg)
  if h then msg = msg .. "\n" .. h end
  local lua_frames = false
  for _, line in ipairs(lines) do
    if not line:match("^%s*%[C%]:") then lua_frames = true end
  end
  if not lua_frames then return msg end   -- a builtin called from the prompt: the message says it all
  return msg .. "\nstack traceback:\n" .. table.concat(lines, "\n")
end

-- ---- :help --------------------------------------------------------------------------------

-- Words wrapped to the width, each line starting with indent.
local function wrap(words, indent, width)
  local lines, line = {}, indent
  for _, w in ipairs(words) do
    if #line > #indent and #line + 1 + #w > width then
      lines[#lines + 1] = line
      line = indent
    end
    line = line .. (#line > #indent and " " or "") .. w
  end
  if #line > #indent then lines[#lines + 1] = line end
  return table.concat(lines, "\n")
end

local function width()
  local cols = native.columns and native.columns() or 80
  return math.max(40, math.min(cols, 100) - 1)
end

local function help_entry(e)
  local a = help.areas[e.area]
  for _, form in ipairs(help.forms(e)) do out(form, "\n") end
  local words = {}
  for w in e.desc:gmatch("%S+") do words[#words + 1] = w end
  out(wrap(words, "  ", width()), "\n")
  local more = a.guide and ("; more in docs/" .. a.guide) or ""
  out("  (", a.title, more, ")\n")
end

local function help_area(a)
  local w = width()
  local words = {}
  for word in (a.title .. ": " .. a.intro):gmatch("%S+") do words[#words + 1] = word end
  out(wrap(words, "", w), "\n")
  for _, e in ipairs(a.entries) do
    for _, form in ipairs(help.forms(e)) do out("  ", form, "\n") end
    local dw = {}
    for word in e.desc:gmatch("%S+") do dw[#dw + 1] = word end
    out(wrap(dw, "      ", w), "\n")
  end
end

-- "  label   text" with the text wrapped under itself from column col.
local function hanging(label, text, col, w)
  local words = {}
  for word in text:gmatch("%S+") do words[#words + 1] = word end
  local body = wrap(words, string.rep(" ", col), w)
  local first = ("  " .. label .. string.rep(" ", col)):sub(1, col)
  if #label + 3 > col then return "  " .. label .. "\n" .. body end
  return first .. body:sub(col + 1)
end

local function help_index()
  local w = width()
  out("Commands (everything else is Lua; expressions print their values):\n")
  for _, e in ipairs(help.areas.repl.entries) do
    out(hanging(help.forms(e)[1], e.desc, 29, w), "\n")
  end
  for _, a in ipairs(help.areas) do
    if a.id ~= "repl" then
      local names = {}
      for i, e in ipairs(a.entries) do names[i] = e.name end
      out(a.title, " (:help ", a.id, "):\n", wrap(names, "  ", w), "\n")
    end
  end
  out(wrap({":help", "NAME", "shows", "a", "signature", "and", "what", "it", "does", "(:help",
            "lerp),", ":help", "AREA", "a", "whole", "area", "(:help", "draw).", "Tab",
            "completes", "names."}, "", w), "\n")
end

-- Names close to a misspelt one: same prefix, or containing it.
local function suggestions(name)
  local found = {}
  local lname = name:lower()
  for _, e in ipairs(help.entries) do
    local n = e.name:lower()
    if n:find(lname, 1, true) or lname:find(n, 1, true) and #n > 1
       or n:sub(1, 3) == lname:sub(1, 3) and #lname >= 3 then
      found[#found + 1] = e.name
    end
  end
  return found
end

local function cmd_help(args)
  local name = args[1]
  if not name then return help_index() end
  local e = help.find(name)
  if e then return help_entry(e) end
  local a = help.areas[name]
  if a and type(a) == "table" then return help_area(a) end
  local alts = suggestions(name)
  out("no help for '", name, "'", #alts > 0 and ("; did you mean " .. table.concat(alts, ", ") .. "?") or "",
      "\n:help lists everything\n")
end

-- ---- the other commands ---------------------------------------------------------------------

local function need(args, n, usage)
  if #args < n then error("usage: " .. usage, 0) end
end

local commands = {
  help = cmd_help,
  show = function(args)
    local cols = args[1] and math.tointeger(tonumber(args[1]))
    if args[1] and not cols then error("usage: " .. help.by_name[":show"].sig, 0) end
    native.show(cols)
  end,
  save = function(args)
    need(args, 1, help.by_name[":save"].sig)
    local ok, err = native.save(args[1], args[2])
    if not ok then error(err, 0) end
    out("wrote ", args[1], "\n")
  end,
  load = function(args)
    need(args, 1, help.by_name[":load"].sig)
    local _, err = native.load(args[1])   -- a script's own errors are printed by the host
    if err then error(err, 0) end
  end,
  clear = function()
    native.clear()
  end,
  watch = function(args)
    if args[1] == "off" then
      native.watch(false)
      out("not watching\n")
    elseif args[1] then
      native.watch(args[1])
      out("watching ", args[1], "\n")
    else
      local w = native.watch()
      out(w and ("watching " .. w) or "not watching (:watch FILE starts)", "\n")
    end
  end,
  quit = function()
    return true
  end,
}
M.commands = commands

-- Split a command's arguments at spaces; "..." or '...' quote a file name with spaces.
local function split_args(s)
  local args = {}
  local i = 1
  while i <= #s do
    local c = s:sub(i, i)
    if c:match("%s") then
      i = i + 1
    elseif c == '"' or c == "'" then
      local j = s:find(c, i + 1, true) or #s + 1
      args[#args + 1] = s:sub(i + 1, j - 1)
      i = j + 1
    else
      local j = s:find("%s", i) or #s + 1
      args[#args + 1] = s:sub(i, j - 1)
      i = j
    end
  end
  return args
end

-- The command named by word: exact, or an unambiguous prefix (:q, :sh).
local function find_command(word)
  if commands[word] then return word end
  local found
  for name in pairs(commands) do
    if name:sub(1, #word) == word then
      if found then return nil, "ambiguous" end
      found = name
    end
  end
  return found
end

-- Run a command line (":save pic.png"); true means quit.
function M.command(line)
  local word, rest = line:match("^%s*:(%S*)%s*(.-)%s*$")
  local name, why = find_command(word)
  if not name or word == "" then
    local names = {}
    for _, e in ipairs(help.areas.repl.entries) do names[#names + 1] = e.name end
    error((why == "ambiguous" and "ambiguous command ':" or "unknown command ':") .. word ..
          "'; the commands are " .. table.concat(names, " "), 0)
  end
  return commands[name](split_args(rest)) == true
end

-- ---- completion ---------------------------------------------------------------------------

local keywords = {"and", "break", "do", "else", "elseif", "end", "false", "for", "function",
                  "goto", "if", "in", "local", "nil", "not", "or", "repeat", "return", "then",
                  "true", "until", "while"}

-- The names after "v." (fields and methods) or "v:" (methods only): the string keys of a
-- table and of the tables its metatables' __index chain leads to.  When __index is a function
-- (points, simplices), the fields it computes come from the help registry (fields_of) and
-- the methods from the tables it holds as upvalues.
local function keys_of(v, methods_only, into)
  local seen = {}
  local function add(k, x)
    if is_identifier(k) and not seen[k] and (not methods_only or type(x) == "function") then
      seen[k] = true
      into[#into + 1] = k
    end
  end
  local depth = 0
  while v ~= nil and depth < 8 do
    depth = depth + 1
    if type(v) == "table" then
      for k, x in pairs(v) do add(k, x) end
    end
    local mt = debug.getmetatable(v)
    local index = type(mt) == "table" and rawget(mt, "__index") or nil
    if type(index) == "table" then
      v = index
    else
      if type(index) == "function" then
        local name = rawget(mt, "__name")
        if help.fields_of[name] then
          local obj = v
          for _, k in ipairs(help.fields_of[name]) do   -- only those this value has (A.z in 3-D)
            local ok, x = pcall(function() return obj[k] end)
            if ok and x ~= nil then add(k, x) end
          end
        end
        for i = 1, 8 do
          local _, up = debug.getupvalue(index, i)
          if up == nil and i > 1 then break end
          if type(up) == "table" and up ~= mt then
            for k, x in pairs(up) do
              if type(x) == "function" then add(k, x) end
            end
          end
        end
      end
      v = nil
    end
  end
  return into
end

-- Look up a dotted path ("math", "a.b") from the globals, without raising errors.
local function resolve(path)
  local v = _G
  for part in path:gmatch("[^.]+") do
    if not is_identifier(part) then return nil end
    local ok, x = pcall(function() return v[part] end)
    if not ok then return nil end
    v = x
    if v == nil then return nil end
  end
  return v
end

local function sorted_matches(list, prefix, decorate)
  local result, seen = {}, {}
  for _, k in ipairs(list) do
    if k:sub(1, #prefix) == prefix and not seen[k] then
      seen[k] = true
      result[#result + 1] = decorate and decorate(k) or k
    end
  end
  table.sort(result)
  return result
end

-- Candidates for the word `text`, with `before` the line up to it.  Returns a list of full
-- replacements for text, or "files" for file-name completion.
function M.complete(text, before)
  local cmd = before:match("^%s*:(%a+)%s")
  if cmd then
    local name = find_command(cmd)
    if name == "load" or name == "save" or name == "watch" then return "files" end
    if name == "help" then
      local names = {}
      for _, e in ipairs(help.entries) do names[#names + 1] = e.name end
      for _, a in ipairs(help.areas) do names[#names + 1] = a.id end
      return sorted_matches(names, text)
    end
    return {}
  end
  if before:match("^%s*$") and text:sub(1, 1) == ":" then
    local names = {}
    for _, e in ipairs(help.areas.repl.entries) do names[#names + 1] = e.name end
    local found = sorted_matches(names, text)
    if #found == 1 then found[1] = found[1] .. " " end   -- ready for the argument
    return found
  end
  local head, sep, part = text:match("^(.*)([.:])([%w_]*)$")
  if not head then
    if not text:match("^[%a_]?[%w_]*$") then return {} end
    local names = keys_of(_G, false, {})
    for _, k in ipairs(keywords) do names[#names + 1] = k end
    return sorted_matches(names, text)
  end
  if head:find(":", 1, true) or head == "" then return {} end
  local v = resolve(head)
  if v == nil then return {} end
  local found = sorted_matches(keys_of(v, sep == ":", {}), part, function(k) return head .. sep .. k end)
  if sep == ":" and #found == 1 then found[1] = found[1] .. "(" end   -- a method is called
  return found
end

return M
