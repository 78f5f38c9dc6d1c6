-- A mutational fuzzer over QBasic programs: each case takes a program of the corpus, changes it
-- a little (a byte, a deleted span, a repeated or borrowed line, an inserted keyword or
-- number), translates it and runs it under an instruction budget.
--
--   pointcalc bas_fuzz.lua SEED CASES PROGRAM.bas... [--log FILE]
--
-- A crash ends the process (the log, default bas_fuzz.log, holds the program that did it).
-- Counted: translations refused with a located message ("NAME.bas:LINE: ..."), runs that
-- ended with a located QBasic error, and the defects: a message without a line, an internal
-- error of the translator, a translation that is not valid Lua.  Prints the counts; exits 1
-- when there is a defect.

local seed, cases = tonumber(arg[1]) or 15, tonumber(arg[2]) or 500
local files, logname = {}, "bas_fuzz.log"
do
  local i = 3
  while arg[i] do
    if arg[i] == "--log" then logname = arg[i + 1]; i = i + 2
    else files[#files + 1] = arg[i]; i = i + 1 end
  end
end
assert(#files > 0, "bas_fuzz.lua: give the corpus programs")

local corpus = {}
for _, f in ipairs(files) do
  local h = assert(io.open(f, "rb"))
  corpus[#corpus + 1] = h:read("a")
  h:close()
end

local rng = (function()   -- xorshift, as in api_fuzz.lua
  local s = seed * 2654435761 % 4294967296 + 1
  return function(n)
    s = s ~ (s << 13) & 0xffffffff
    s = s ~ (s >> 17)
    s = s ~ (s << 5) & 0xffffffff
    return s % n + 1
  end
end)()

local tokens = {"GOTO 10", "GOSUB 20", "RETURN", "(", ")", ",", ":", ";", "\"", "'", "FOR I = 1 TO",
  "NEXT", "NEXT I", "DIM A(", "DIM A(1E+9)", "1E+308", "-32768", "32767", "&H", "&HFFFF", "SUB",
  "END SUB", "FUNCTION", "END FUNCTION", "IF", "THEN", "ELSE", "END IF", "CIRCLE (", "PSET (",
  "LINE -(", "DATA", "READ X", "PRINT", "USING", "SCREEN 13", "SCREEN 99", "PAINT (", "WINDOW",
  "VIEW (", "DEF FN", "SELECT CASE", "CASE", "END SELECT", "DO", "LOOP", "WHILE", "WEND", "\n",
  "0", "-1", "/ 0", "\\ 0", "MOD 0", "^", "X#", "A$", "CHR$(", "STRING$(", "1E+38", "REDIM",
  "OPTION BASE 1", "ON X GOTO", "SWAP", "CONST", "SHARED", "STATIC", "EXIT FOR", "END"}

local function lines_of(s)
  local t = {}
  for l in (s .. "\n"):gmatch("([^\n]*)\n") do t[#t + 1] = l end
  return t
end

local function mutate(src)
  for _ = 1, rng(4) do
    local n = #src
    local kind = rng(6)
    local at = rng(n + 1)
    if kind == 1 and n > 0 then           -- a byte
      src = src:sub(1, at - 1) .. string.char(rng(256) - 1) .. src:sub(at + 1)
    elseif kind == 2 and n > 0 then       -- a span deleted
      src = src:sub(1, at - 1) .. src:sub(at + rng(20))
    elseif kind == 3 then                 -- a token inserted
      src = src:sub(1, at - 1) .. " " .. tokens[rng(#tokens)] .. " " .. src:sub(at)
    elseif kind == 4 then                 -- a line repeated
      local ls = lines_of(src)
      local i = rng(#ls)
      table.insert(ls, rng(#ls + 1), ls[i])
      src = table.concat(ls, "\n")
    elseif kind == 5 then                 -- a line from another program
      local other = lines_of(corpus[rng(#corpus)])
      local ls = lines_of(src)
      table.insert(ls, rng(#ls + 1), other[rng(#other)])
      src = table.concat(ls, "\n")
    else                                  -- a digit changed
      local pos = src:find("%d", at)
      if pos then src = src:sub(1, pos - 1) .. tostring(rng(10) - 1) .. src:sub(pos + 1) end
    end
  end
  return src
end

local qbasic = require "qbasic"
local BUDGET = 300000   -- instructions per run
local log = assert(io.open(logname, "w"))
local counts = {refused = 0, ran = 0, errors = 0, budget = 0, unlocated = 0, internal = 0,
                bad_lua = 0}
local shown = 0
local function defect(kind, case, msg)
  counts[kind] = counts[kind] + 1
  if shown < 20 then
    shown = shown + 1
    io.stderr:write(string.format("%s (case %d): %s\n", kind, case, tostring(msg):gsub("\n.*", "")))
  end
end

for case = 1, cases do
  local name = "fuzz" .. case .. ".bas"
  local src = mutate(corpus[rng(#corpus)])
  log:write(string.format("---- case %d\n%s\n", case, src))
  log:flush()
  local ok, lua, msg = pcall(qbasic.translate, src, name)
  if not ok then
    defect("internal", case, lua)
  elseif not lua then
    if type(msg) ~= "string" or msg:find("internal error", 1, true) then
      defect("internal", case, msg)
    elseif not msg:find("^" .. name:gsub("%.", "%%.") .. ":%d+: ") then
      defect("unlocated", case, msg)
    else
      counts.refused = counts.refused + 1
    end
  else
    local chunk, err = load(lua, "@" .. name, "t")
    if not chunk then
      defect("bad_lua", case, err)
    else
      local over = false
      debug.sethook(function() over = true; error("fuzz budget", 0) end, "", BUDGET)
      local ran, e = pcall(chunk)
      debug.sethook()
      pcall(screen, 12)    -- the next program starts from the default screen
      if ran then
        counts.ran = counts.ran + 1
      elseif over then
        counts.budget = counts.budget + 1
      else
        local text = tostring(e)
        if text:find("^" .. name:gsub("%.", "%%.") .. ":%d+: ") then
          counts.errors = counts.errors + 1
        else
          defect("unlocated", case, text)
        end
      end
    end
  end
end
log:close()
print(string.format("%d cases: %d refused, %d ran, %d QBasic errors, %d over budget; " ..
  "defects: %d unlocated, %d internal, %d invalid Lua", cases, counts.refused, counts.ran,
  counts.errors, counts.budget, counts.unlocated, counts.internal, counts.bad_lua))
if counts.unlocated + counts.internal + counts.bad_lua > 0 then os.exit(1) end
