-- QBasic front end, runtime part 3: PRINT USING.  format(fmt, values) gives the text QBasic's
-- PRINT USING prints for the values, cycling through the format as often as needed.
--
-- Format characters (everything else is printed as it is):
--   !  the first character of a string      \  \  n characters (n = 2 + spaces between)
--   &  the whole string                      _  the next character as it is
--   #  a digit      .  the decimal point     ,  (left of the point) thousands separated by ,
--   +  first or last: the sign, + or -       -  last: - for a negative number, else a space
--   ** leading spaces as *, two more digits  $$ a $ before the number, one more digit
--   **$ both                                  ^^^^ (^^^^^) E+nn (E+nnn) exponential notation
-- A number too wide for its field is printed whole after a %.  Values are numbers (SINGLE, or
-- DOUBLE as {double = v}) or strings.
local M = {}

-- ---- the format as a list of literal texts and fields ----------------------------------------
local function numeric_field(fmt, i)
  local f = { kind = "num", int = 0, dec = 0 }
  local start = i
  local function at(s) return fmt:sub(i, i + #s - 1) == s end
  if at("+") then f.plus_lead = true; i = i + 1 end
  if at("**$") then f.star, f.dollar, f.int = true, true, 3; i = i + 3
  elseif at("**") then f.star, f.int = true, 2; i = i + 2
  elseif at("$$") then f.dollar, f.int = true, 2; i = i + 2 end
  while true do
    local c = fmt:sub(i, i)
    if c == "#" then f.int = f.int + 1
    elseif c == "," and not f.point then f.comma = true; f.int = f.int + 1
    else break end
    i = i + 1
  end
  if fmt:sub(i, i) == "." then
    f.point = true
    i = i + 1
    while fmt:sub(i, i) == "#" do f.dec = f.dec + 1; i = i + 1 end
  end
  if at("^^^^^") then f.exp = 3; i = i + 5
  elseif at("^^^^") then f.exp = 2; i = i + 4 end
  if not f.plus_lead and at("+") then f.plus_trail = true; i = i + 1
  elseif at("-") then f.minus_trail = true; i = i + 1 end
  -- a field needs a digit position: a lone "+" or "." is literal text
  if f.int == 0 and f.dec == 0 and not f.point then return nil, start end
  if f.int == 0 and f.dec == 0 and not f.star and not f.dollar then return nil, start end
  return f, i
end

local cache = setmetatable({}, { __mode = "k" })
local function parse(fmt)
  if cache[fmt] then return cache[fmt] end
  local items, lit = {}, {}
  local function flush()
    if #lit > 0 then items[#items + 1] = { lit = table.concat(lit) }; lit = {} end
  end
  local i, n = 1, #fmt
  while i <= n do
    local c = fmt:sub(i, i)
    local nxt = fmt:sub(i + 1, i + 1)
    local field, j
    if c == "_" then
      lit[#lit + 1] = i < n and nxt or "_"
      i = i + 2
    elseif c == "!" or c == "&" then
      field, j = { kind = "str", width = c == "!" and 1 or nil }, i + 1
    elseif c == "\\" and fmt:find("^ *\\", i + 1) then
      local close = fmt:find("\\", i + 1, true)
      field, j = { kind = "str", width = close - i + 1 }, close + 1
    elseif c == "#" or (c == "." and nxt == "#") or c == "+" or (c == "*" and nxt == "*")
        or (c == "$" and nxt == "$") then
      field, j = numeric_field(fmt, i)
      if not field then lit[#lit + 1] = c; i = i + 1 end
    else
      lit[#lit + 1] = c
      i = i + 1
    end
    if field then
      flush()
      items[#items + 1] = field
      i = j
    end
  end
  flush()
  cache[fmt] = items
  return items
end

-- ---- numbers ---------------------------------------------------------------------------------
local function commas(ip)
  local s = ip:reverse():gsub("(%d%d%d)", "%1,"):reverse()
  return (s:gsub("^,", ""))
end

local function format_number(f, v)
  local neg = v < 0
  local a = math.abs(v)
  local sign_inside = not (f.plus_lead or f.plus_trail or f.minus_trail)
  local width = f.int + (f.plus_lead and 1 or 0)
  local prefix = ""
  if f.plus_lead then prefix = neg and "-" or "+"
  elseif neg and sign_inside then prefix = "-" end
  if f.dollar then prefix = prefix .. "$" end
  local ip, dp, exp_text
  if f.exp then
    -- the mantissa has as many integer digits as the field (less one for the sign)
    local digits = math.max(f.int - (sign_inside and 1 or 0), 0)
    local e = 0
    if a > 0 then e = math.floor(math.log(a, 10)) - digits + 1 end
    local ms = string.format("%." .. f.dec .. "f", a / 10 ^ e)
    if a > 0 and tonumber(ms) >= 10 ^ digits then   -- 9.996 rounded up to 10.00
      e = e + 1
      ms = string.format("%." .. f.dec .. "f", a / 10 ^ e)
    end
    ip, dp = ms:match("^(%d+)%.?(%d*)$")
    exp_text = "E" .. (e < 0 and "-" or "+") .. string.format("%0" .. f.exp .. "d", math.abs(e))
  else
    local s = string.format("%." .. f.dec .. "f", a)
    ip, dp = s:match("^(%d+)%.?(%d*)$")
    if f.comma then ip = commas(ip) end
  end
  local left = prefix .. ip
  -- a leading 0 only where it fits (".##" prints .50, "#.##" of -.5 prints -.50)
  if #left > width and ip == "0" then left = prefix end
  local right = (f.point and ("." .. dp) or "") .. (exp_text or "")
  if f.plus_trail then right = right .. (neg and "-" or "+")
  elseif f.minus_trail then right = right .. (neg and "-" or " ") end
  if #left > width then return "%" .. left .. right end
  return string.rep(f.star and "*" or " ", width - #left) .. left .. right
end

-- ---- the whole statement --------------------------------------------------------------------
-- values: a list of numbers, {double = v} and strings; fail(msg) raises QBasic's error
function M.format(fmt, values, fail)
  local items = parse(fmt)
  local any_field = false
  for _, it in ipairs(items) do if not it.lit then any_field = true end end
  if not any_field then
    if #values > 0 then fail("Illegal function call") end
    return fmt:gsub("_(.)", "%1")
  end
  local out = {}
  local vi, pos = 1, 1
  while true do
    local it = items[pos]
    if not it then
      if vi > #values then break end
      pos = 1
      it = items[1]
    end
    if it.lit then
      out[#out + 1] = it.lit
    else
      if vi > #values then break end
      local v = values[vi]
      vi = vi + 1
      if type(v) == "table" then v = v.double end
      if it.kind == "str" then
        if type(v) ~= "string" then fail("Type mismatch") end
        if it.width then
          v = v:sub(1, it.width)
          v = v .. string.rep(" ", it.width - #v)
        end
        out[#out + 1] = v
      else
        if type(v) ~= "number" then fail("Type mismatch") end
        if v - v ~= 0 then fail("Overflow") end
        out[#out + 1] = format_number(it, v)
      end
    end
    pos = pos + 1
  end
  return table.concat(out)
end

return M
