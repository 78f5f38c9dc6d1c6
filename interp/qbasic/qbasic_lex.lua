-- QBasic front end, part 1: the lexer.  One physical line at a time becomes a list of tokens.
--
-- Token kinds (field t):
--   num   v = value, ty = "int"|"long"|"single"|"double", text = source spelling
--   str   v = the string (a string may run to the end of the line unterminated, as in QBasic)
--   id    v = lower-case name without suffix, sfx = "$"|"%"|"&"|"!"|"#"|nil, text = spelling
--   kw    v = lower-case keyword, with its "$" for string functions (left$, chr$, ...)
--   op    v = one of + - * / \ ^ = < > <= >= <> ( ) , ; : #
--   data  items = {{text=, quoted=}, ...}   everything after DATA up to an unquoted ':'
--   field v = ".x" after ")" without its dot (a(i).x; a.x alone is one id, split later)
--   eol   the end of the line; rem = true when a comment ended it
-- Every token has col, its 1-based column.
local M = {}

-- QBasic's reserved words: the one keyword table (qbasic_keywords.lua)
local reserved = require("qbasic_keywords").reserved
M.reserved = reserved

local function lex_error(msg, col)
  error({ qb = true, msg = msg or "Syntax error", col = col }, 0)
end

-- DATA: items separated by commas up to an unquoted ':' or the end of the line.  Unquoted
-- items are trimmed; a quoted item keeps its text exactly.
local function lex_data(s, i)
  local items = {}
  local n = #s
  while true do
    -- skip blanks
    while i <= n and s:sub(i, i):match("[ \t]") do i = i + 1 end
    local item
    if s:sub(i, i) == '"' then
      local j = s:find('"', i + 1, true)
      local text = s:sub(i + 1, (j or n + 1) - 1)
      item = { text = text, quoted = true }
      i = j and j + 1 or n + 1
      while i <= n and s:sub(i, i):match("[ \t]") do i = i + 1 end
      local c = s:sub(i, i)
      if i <= n and c ~= "," and c ~= ":" then lex_error("Syntax error", i) end
    else
      local j = i
      while j <= n and not s:sub(j, j):match("[,:]") do j = j + 1 end
      item = { text = s:sub(i, j - 1):match("^%s*(.-)%s*$"), quoted = false }
      i = j
    end
    items[#items + 1] = item
    local c = s:sub(i, i)
    if c == "," then
      i = i + 1
    else
      return items, i   -- at ':' or past the end
    end
  end
end

-- The value of &H/&O digits worth v (long: written with the & suffix), as QBasic reads them in
-- programs and in VAL: an INTEGER, where &H8000..&HFFFF are the negative integers, unless the
-- value needs a LONG or has the suffix (&HFFFFFFFF is -1).  Returns value, type; nil beyond
-- 32 bits (Overflow).
function M.radix_value(v, long)
  local ty = (long or v > 0xFFFF) and "long" or "int"
  if ty == "int" and v >= 0x8000 then v = v - 0x10000 end
  if ty == "long" and v >= 0x80000000 then
    if v > 0xFFFFFFFF then return nil end
    v = v - 0x100000000
  end
  return v, ty
end

-- a number literal at position i; returns the token and the next position
local function lex_number(s, i)
  local col = i
  local c = s:sub(i, i)
  if c == "&" then
    local kind = s:sub(i + 1, i + 1):upper()
    local digits, j, base
    if kind == "H" then
      digits = s:match("^[%x]+", i + 2); base = 16; j = i + 2
    elseif kind == "O" then
      digits = s:match("^[0-7]+", i + 2); base = 8; j = i + 2
    else
      digits = s:match("^[0-7]+", i + 1); base = 8; j = i + 1
    end
    if not digits then lex_error("Syntax error", col) end
    j = j + #digits
    local sfx = s:sub(j, j)
    if sfx == "&" or sfx == "%" then j = j + 1 end
    -- (more than 11 significant digits would wrap around in tonumber: certainly an Overflow)
    local v, ty
    if #(digits:gsub("^0+", "")) <= 11 then
      v, ty = M.radix_value(tonumber(digits, base), sfx == "&")
    end
    if not v then lex_error("Overflow", col) end
    return { t = "num", v = v, ty = ty, text = s:sub(col, j - 1), col = col }, j
  end
  local mant = s:match("^%d*%.?%d*", i)
  if mant == "" or mant == "." then lex_error("Syntax error", col) end
  local j = i + #mant
  local exp, expch = "", nil
  local e = s:sub(j, j)
  if e == "e" or e == "E" or e == "d" or e == "D" then
    local ex = s:match("^[eEdD][+-]?%d+", j)
    if ex then
      exp = ex; expch = e:upper(); j = j + #ex
    else
      -- "1E" alone (QBasic accepts it as 1E+00); keep it simple: a bare E is an exponent of 0
      local bare = s:match("^[eEdD][+-]?", j)
      exp = bare; expch = e:upper(); j = j + #bare
    end
  end
  local sfx = s:sub(j, j)
  if sfx:match("[!#%%&]") then j = j + 1 else sfx = nil end
  local text = s:sub(col, j - 1)
  local numtext = mant .. (exp ~= "" and ("e" .. exp:sub(2)) or "")
  if numtext:match("e[+-]?$") then numtext = numtext .. "0" end
  local v = tonumber(numtext)
  if not v then lex_error("Syntax error", col) end
  local ty
  local digits = #(mant:gsub("%.", ""):gsub("^0+", ""))
  if sfx == "%" then ty = "int"
  elseif sfx == "&" then ty = "long"
  elseif sfx == "!" then ty = "single"
  elseif sfx == "#" then ty = "double"
  elseif expch == "D" then ty = "double"
  elseif expch == "E" then ty = digits > 7 and "double" or "single"
  elseif mant:find(".", 1, true) then ty = digits > 7 and "double" or "single"
  elseif v <= 32767 then ty = "int"
  elseif v <= 2147483647 then ty = "long"
  else ty = digits > 7 and "double" or "single" end
  if (ty == "int" or ty == "long") and v ~= math.floor(v) then
    -- 1.5% : QBasic rounds the constant
    v = v - math.floor(v) == 0.5 and (math.floor(v) % 2 == 0 and math.floor(v) or math.floor(v) + 1)
        or math.floor(v + 0.5)
  end
  if ty == "int" and (v > 32767 or v < -32768) then lex_error("Overflow", col) end
  if ty == "long" and (v > 2147483647 or v < -2147483648) then lex_error("Overflow", col) end
  -- a SINGLE beyond float32 (1E39) or a DOUBLE beyond double (1D309) is QBasic's Overflow,
  -- never Lua's inf (which would read as the variable inf)
  -- (the parser says so where the number is a value; as a line number it is a Syntax error)
  local overflow = v - v ~= 0 or (ty == "single" and math.abs(v) >= 3.4028235677973366e38)
  return { t = "num", v = v, ty = ty, text = text, col = col, overflow = overflow }, j
end

local two_char_ops = { ["<="] = "<=", [">="] = ">=", ["<>"] = "<>", ["=<"] = "<=", ["=>"] = ">=",
  ["><"] = "<>" }

-- Lex one physical line (without its line break).  Returns the token list.
function M.line(s)
  local toks = {}
  local i, n = 1, #s
  local stmt_start = true      -- the next token starts a statement (for DATA and REM)
  while true do
    while i <= n and s:sub(i, i):match("[ \t\r\f\v]") do i = i + 1 end
    if i > n then break end
    local c = s:sub(i, i)
    local col = i
    if c == "'" then
      toks[#toks + 1] = { t = "eol", rem = true, col = col }
      return toks
    elseif c == '"' then
      local j = s:find('"', i + 1, true)
      toks[#toks + 1] = { t = "str", v = s:sub(i + 1, (j or n + 1) - 1), col = col }
      i = j and j + 1 or n + 1
      stmt_start = false
    elseif c:match("%d") or (c == "." and s:sub(i + 1, i + 1):match("%d")) or c == "&" then
      local tok
      tok, i = lex_number(s, i)
      toks[#toks + 1] = tok
      stmt_start = false
    elseif c:match("%a") then
      local name = s:match("^[%a][%w%.]*", i)
      i = i + #name
      local sfx = s:sub(i, i)
      if sfx:match("[%$%%&!#]") then i = i + 1 else sfx = nil end
      local low = name:lower()
      local kwname = low .. (sfx == "$" and "$" or "")
      if reserved[kwname] and (sfx == nil or sfx == "$") then
        if kwname == "rem" and (stmt_start or true) then
          toks[#toks + 1] = { t = "kw", v = "rem", col = col }
          toks[#toks + 1] = { t = "eol", rem = true, col = col }
          return toks
        end
        toks[#toks + 1] = { t = "kw", v = kwname, col = col }
        if kwname == "data" then
          local items
          items, i = lex_data(s, i)
          toks[#toks + 1] = { t = "data", items = items, col = col }
          stmt_start = false
        else
          stmt_start = (kwname == "then" or kwname == "else")
        end
      elseif reserved[low] and sfx ~= "$" and sfx ~= nil and low ~= "fn" then
        -- a keyword with a numeric type suffix, e.g. "line%": not a valid name
        lex_error("Syntax error", col)
      else
        toks[#toks + 1] = { t = "id", v = low, sfx = sfx, text = s:sub(col, i - 1), col = col }
        stmt_start = false
      end
    else
      local two = s:sub(i, i + 1)
      if two_char_ops[two] then
        toks[#toks + 1] = { t = "op", v = two_char_ops[two], col = col }
        i = i + 2
      elseif c:match("[%+%-%*/\\%^=<>%(%),;:#]") then
        toks[#toks + 1] = { t = "op", v = c, col = col }
        i = i + 1
      elseif c == "?" then
        toks[#toks + 1] = { t = "kw", v = "print", col = col }
        i = i + 1
      elseif c == "." and s:sub(i + 1, i + 1):match("%a") and #toks > 0
          and toks[#toks].t == "op" and toks[#toks].v == ")" then
        -- a(i).x: a field of an array element of a TYPE (a.x alone lexes as one name)
        local name = s:match("^[%a][%w%.]*", i + 1)
        toks[#toks + 1] = { t = "field", v = name:lower(), col = col }
        i = i + 1 + #name
      else
        lex_error("Syntax error", col)
      end
      stmt_start = (c == ":")
    end
  end
  toks[#toks + 1] = { t = "eol", col = n + 1 }
  return toks
end

return M
