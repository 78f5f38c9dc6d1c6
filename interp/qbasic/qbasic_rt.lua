-- QBasic front end, part 4: the runtime of translated programs.
--
-- A translated program starts with
--     local _ENV = require("qbasic_rt").new(_ENV, "prog.bas") return run(function() ...
-- so its module variables are fields of the environment made here, next to the helpers below
-- (QBasic semantics that plain Lua does not give: SINGLE rounding, CINT, "Division by zero",
-- -1/0 truth values, arrays with QBasic bounds, DATA, PRINT formatting) and to wrappers of the
-- pointcalc drawing layer that check arguments the way QBasic does.
--
-- Errors are QBasic's messages raised at the caller's level, so they read
-- "prog.bas:LINE: Illegal function call" with the program's line.
local M = {}

-- every global name a translated program may use besides its own variables: the translator
-- keeps user names clear of these
M.names = {
  "csng", "cint", "clng", "cdbl", "sin", "cos", "tan", "atn", "sqr", "exp", "log", "abs", "int",
  "fix", "sgn", "rnd", "timer", "randomize", "div", "idiv", "mod", "pow", "imul", "lmul",
  "band", "bor", "bxor", "bnot", "beqv", "bimp", "truth", "both", "either", "for_test", "len",
  "left", "right", "mid", "str", "val", "chr", "asc", "space", "string_", "lcase", "ucase",
  "ltrim", "rtrim", "instr", "hex", "oct", "dim", "dim_str", "lbound", "ubound", "read_number", "read_string", "restore",
  "qprint", "zone", "nonl", "tab", "spc", "dbl", "lng", "screen", "cls", "color", "palette",
  "pset", "preset", "line", "line_to", "circle", "paint", "point", "window", "view", "step_xy",
  "stop", "return_without_gosub", "on_index", "run", "case", "on", "start", "_ENV", "_",
  "cat", "fixstr", "fixed_init", "dim_fixed", "record", "dim_rec", "rec_copy", "erase",
  "mid_set", "static_new", "qprint_using", "trap", "on_error", "resume_ok", "resume_at",
  "error_n", "err_", "erl_", "mki", "mkl", "mks", "mkd", "cvi", "cvl", "cvs", "cvd", "lset",
  "rset", "direct_lines", "skipped_includes", "palette_using", "clear", "chain", "common", "run_program",
  "fprint_using", "next_without_for", "gosub_push", "gosub_pop", "gret", "_gs", "proc_end",
}
local screen_rt = require("qbasic_screen")
local hw_rt = require("qbasic_hw")
local files_rt = require("qbasic_files")
for _, n in ipairs(screen_rt.names) do M.names[#M.names + 1] = n end
for _, n in ipairs(hw_rt.names) do M.names[#M.names + 1] = n end
for _, n in ipairs(files_rt.names) do M.names[#M.names + 1] = n end

local radix_value = require("qbasic_lex").radix_value
local floor, huge = math.floor, math.huge
local IFC = "Illegal function call"

-- SINGLE rounding and QBasic's RND generator are the C core's (interp/qbasic/qbnum.c, as the qb
-- table of pointcalc): the translated program and Lua scripts share one generator
local pc = require("pointcalc")
local qb = pc.qb
local f32 = qb.f32

local function round_even(x)
  local f = floor(x)
  local d = x - f
  if d > 0.5 or (d == 0.5 and f % 2 ~= 0) then f = f + 1 end
  return f
end

-- ---- number formatting (PRINT, STR$) -------------------------------------------------------
-- As QBasic: 7 significant digits for SINGLE, 16 for DOUBLE; fixed notation while the digits
-- fit (exponent <= 6 and no more than 7 decimals for SINGLE), else 1.234568E+07 / D+ for DOUBLE.
local function fmt_float(v, double)
  if v == 0 then return "0" end
  local a = math.abs(v)
  local s = string.format(double and "%.15E" or "%.6E", a)
  local mant, ex = s:match("^(%d%.%d+)E([%+%-]%d+)$")
  if not mant then return tostring(v) end          -- inf, nan
  if double and mant:sub(-1) == "9" then
    s = string.format("%.14E", a)
    mant, ex = s:match("^(%d%.%d+)E([%+%-]%d+)$")
  end
  local digits = (mant:gsub("%.", "")):gsub("0+$", "")
  local nd = #digits
  local e = tonumber(ex)
  local maxe, mind = 6, -8
  if double then maxe, mind = 15, -17 end
  local body
  if e <= maxe and e - nd >= mind then
    local dec = nd - e - 1
    if dec < 0 then dec = 0 end
    body = string.format("%." .. dec .. "f", a)
    if dec > 0 then body = body:gsub("0+$", "") end
    body = body:gsub("^0%.", ".")
  else
    body = digits:sub(1, 1) .. (nd > 1 and ("." .. digits:sub(2)) or "")
      .. (double and "D" or "E") .. (e < 0 and "-" or "+") .. string.format("%02d", math.abs(e))
  end
  return (v < 0 and "-" or "") .. body
end
M.fmt_float = fmt_float

-- PRINT and STR$ text of v as kind ("single", "double", "long"); a value beyond its type's
-- range is QBasic's Overflow (raised at `level` as error() counts from the caller), never "inf"
local function fmt_number(v, kind, level)
  if kind == "long" then
    return string.format("%d", v)
  end
  if kind ~= "double" then v = f32(v) end
  if v - v ~= 0 then error("Overflow", level + 1) end
  return fmt_float(v, kind == "double")
end

-- READ s$ of a numeric DATA item: its text.  DATA items are numbers in the translation; an
-- item whose text is not data_text(value) (DATA 007, 1.50, 3.5E2, an empty item) also carries
-- its text, as {value, text}.
local function data_text(v, level)
  return fmt_number(v, v == floor(v) and math.abs(v) < 2 ^ 31 and "long" or "double", level + 1)
end
M.data_text = function(v) return data_text(v, 1) end

local STOP = setmetatable({}, { __tostring = function() return "END" end })

-- A runtime error as QBasic reports it: "prog.bas:LINE: message", the line the program's own
-- (a message raised inside the runtime or the host names it by the innermost frame of the
-- program), Lua's stack overflow as QBasic's "Out of stack space", and no Lua traceback (the
-- error is a table whose __tostring the host prints as it is); PC_QBASIC_TRACEBACK=1 in the
-- environment keeps the traceback, for debugging the translator.
local dbg = debug
local Message = { __tostring = function(m) return m.text end }
local function qbasic_message_for(chunkname, program)
  -- the name Lua gives the program's chunk (prog.bas, or prog.lua for a saved translation)
  if dbg then chunkname = dbg.getinfo(program, "S").short_src or chunkname end
  return function(err)
    if err == STOP or getmetatable(err) == Message then return err end
    local msg = tostring(err)
    local line
    local prefix = chunkname .. ":"
    if msg:sub(1, #prefix) == prefix then
      line, msg = msg:sub(#prefix + 1):match("^(%d+): (.*)$")
    end
    if not line and dbg then
      for level = 2, 200 do
        local info = dbg.getinfo(level, "Sl")
        if not info then break end
        if info.short_src == chunkname and info.currentline > 0 then line = info.currentline break end
      end
    end
    msg = (msg or tostring(err)):gsub("^%[?[^%]:]*%]?:%d+: ", "")
    if msg:find("stack overflow", 1, true) then msg = "Out of stack space"
    elseif msg:find("not enough memory", 1, true) then msg = "Out of memory" end
    local text = chunkname .. ":" .. (line or "?") .. ": " .. msg
    if dbg and os.getenv("PC_QBASIC_TRACEBACK") == "1" then text = dbg.traceback(text, 2) end
    return setmetatable({ text = text }, Message)
  end
end


-- ---- the functions a program calls that keep no state of their own --------------------
-- (copied into each program's environment by new)
local PURE = {}

-- ---- numbers --------------------------------------------------------------------------
-- (in C: the statement every SINGLE assignment runs; bench/qbasic)
PURE.csng = qb.csng
function PURE.cdbl(x)
  if x - x ~= 0 then error("Overflow", 2) end
  return x
end
local function to_int(x, lo, hi, level)
  if x ~= x then error("Overflow", level + 1) end
  local r = round_even(x)
  if r < lo or r > hi then error("Overflow", level + 1) end
  return math.tointeger(r) or r
end
function PURE.cint(x) local r = to_int(x, -32768, 32767, 2) return r end
function PURE.clng(x) local r = to_int(x, -2147483648, 2147483647, 2) return r end
local function long(x, level) return to_int(x, -2147483648, 2147483647, level + 1) end

-- INTEGER and LONG products: computed in floating point (never wrapping around) and
-- checked against the type's range, as QBasic does
function PURE.imul(a, b)
  local r = (a + 0.0) * b
  if not (r >= -32768 and r <= 32767) then error("Overflow", 2) end
  return math.tointeger(r) or r
end
function PURE.lmul(a, b)
  local r = (a + 0.0) * b
  if not (r >= -2147483648 and r <= 2147483647) then error("Overflow", 2) end
  return math.tointeger(r) or r
end
function PURE.div(a, b)
  if b == 0 then error("Division by zero", 2) end
  return a / b
end
function PURE.idiv(a, b)
  a, b = long(a, 2), long(b, 2)
  if b == 0 then error("Division by zero", 2) end
  local q = a // b
  if q < 0 and q * b ~= a then q = q + 1 end
  return q
end
function PURE.mod(a, b)
  a, b = long(a, 2), long(b, 2)
  if b == 0 then error("Division by zero", 2) end
  return math.fmod(a, b)
end
function PURE.pow(a, b)
  if a == 0 and b < 0 then error("Division by zero", 2) end
  if a < 0 and b ~= floor(b) then error(IFC, 2) end
  return a ^ b
end
function PURE.band(a, b) return long(a, 2) & long(b, 2) end
function PURE.bor(a, b) return long(a, 2) | long(b, 2) end
function PURE.bxor(a, b) return long(a, 2) ~ long(b, 2) end
function PURE.beqv(a, b) return ~(long(a, 2) ~ long(b, 2)) end
function PURE.bimp(a, b) return (~long(a, 2)) | long(b, 2) end
function PURE.bnot(a) return ~long(a, 2) end
function PURE.truth(c) if c then return -1 end return 0 end
function PURE.both(a, b) return a and b end
function PURE.either(a, b) return a or b end
function PURE.for_test(v, limit, step)
  if step >= 0 then return v <= limit end
  return v >= limit
end

PURE.sin, PURE.cos, PURE.tan, PURE.atn, PURE.abs = math.sin, math.cos, math.tan, math.atan, math.abs
function PURE.sqr(x)
  if x < 0 then error(IFC, 2) end
  return math.sqrt(x)
end
function PURE.log(x)
  if x <= 0 then error(IFC, 2) end
  return math.log(x)
end
function PURE.exp(x)
  local r = math.exp(x)
  if r == huge then error("Overflow", 2) end
  return r
end
function PURE.int(x) return floor(x) end
function PURE.fix(x) if x >= 0 then return floor(x) end return math.ceil(x) end
function PURE.sgn(x) if x > 0 then return 1 elseif x < 0 then return -1 end return 0 end
function PURE.rnd(n) return qb.rnd(n or 1) end
function PURE.randomize(n)
  if n - n ~= 0 then error("Overflow", 2) end
  qb.randomize(n)
end
function PURE.on_index(v)
  local r = to_int(v, -32768, 32767, 2)
  if r < 0 or r > 255 then error(IFC, 2) end
  return r
end

-- ---- strings ----------------------------------------------------------------------------
-- a length or count (LEFT$, SPACE$, STRING$...) is an INTEGER, as QBasic's strings are at
-- most 32767 characters: SPACE$(2000000000) is Overflow, not 2 GB of spaces
local function count(n, level)
  local r = to_int(n, -32768, 32767, level + 1)
  if r < 0 then error(IFC, level + 1) end
  return r
end
function PURE.len(s) return #s end
function PURE.left(s, n) n = count(n, 2) return s:sub(1, n) end
function PURE.right(s, n) n = count(n, 2) if n == 0 then return "" end return s:sub(-n) end
function PURE.mid(s, start, n)
  start = long(start, 2)
  if start < 1 then error(IFC, 2) end
  if n == nil then return s:sub(start) end
  n = count(n, 2)
  return s:sub(start, start + n - 1)
end
function PURE.str(x, kind)
  local t = fmt_number(x, kind, 2)
  if t:sub(1, 1) ~= "-" then t = " " .. t end
  return t
end
function PURE.val(s)
  s = s:gsub("[ \t\n]", "")
  -- &H and &O numbers as in a program: VAL("&HFFFF") is -1, VAL("&HFFFF&") 65535
  local digits, long = s:match("^&[Hh](%x+)(&?)")
  local base = 16
  if not digits then digits, long = s:match("^&[Oo]?([0-7]+)(&?)"); base = 8 end
  if digits then
    local v
    if #(digits:gsub("^0+", "")) <= 11 then
      v = radix_value(tonumber(digits, base), long == "&")
    end
    if not v then error("Overflow", 2) end
    return v
  end
  local num = s:match("^[+-]?%d*%.?%d*[eEdD][+-]?%d+") or s:match("^[+-]?%d*%.?%d*")
  num = num:gsub("[dD]", "e")
  return tonumber(num) or 0
end
function PURE.chr(n)
  n = long(n, 2)
  if n < 0 or n > 255 then error(IFC, 2) end
  return string.char(n)
end
function PURE.asc(s)
  if s == "" then error(IFC, 2) end
  return s:byte(1)
end
function PURE.space(n) n = count(n, 2) return string.rep(" ", n) end
function PURE.string_(n, c)
  n = count(n, 2)
  if type(c) == "string" then
    if c == "" then error(IFC, 2) end
    return string.rep(c:sub(1, 1), n)
  end
  c = long(c, 2)
  if c < 0 or c > 255 then error(IFC, 2) end
  return string.rep(string.char(c), n)
end
function PURE.lcase(s) return s:lower() end
function PURE.ucase(s) return s:upper() end
function PURE.ltrim(s) return (s:gsub("^ +", "")) end
function PURE.rtrim(s) return (s:gsub(" +$", "")) end
function PURE.instr(a, b, c)
  local start, s, t = 1, a, b
  if type(a) ~= "string" then
    start = long(a, 2)
    if start < 1 or start > 32767 then error(IFC, 2) end
    s, t = b, c
  end
  if start > #s then return 0 end
  if t == "" then return start end
  return s:find(t, start, true) or 0
end
local function radix(n, fmt)
  n = long(n, 3)
  if n < 0 then n = n >= -32768 and n + 0x10000 or n + 0x100000000 end
  return string.format(fmt, n)
end
function PURE.hex(n) local r = radix(n, "%X") return r end
function PURE.oct(n) local r = radix(n, "%o") return r end

-- ---- numbers as bytes: MKI$ MKL$ MKS$ MKD$ and CVI CVL CVS CVD; LSET and RSET ------------------
-- little-endian two's complement INTEGER and LONG, IEEE single (rounded as qb.f32) and double,
-- as QBasic 1.1 and QuickBASIC 4.5 store them (the MBF forms are MKSMBF$ and friends)
function PURE.mki(n) return string.pack("<i2", to_int(n, -32768, 32767, 2)) end
function PURE.mkl(n) return string.pack("<i4", to_int(n, -2147483648, 2147483647, 2)) end
function PURE.mks(x)
  local r = f32(x)
  if r - r ~= 0 then error("Overflow", 2) end
  return string.pack("<f", r)
end
function PURE.mkd(x) return string.pack("<d", x) end
local function cv(s, fmt, n)
  if #s < n then error(IFC, 3) end
  return (string.unpack(fmt, s))
end
function PURE.cvi(s) local r = cv(s, "<i2", 2) return r end
function PURE.cvl(s) local r = cv(s, "<i4", 4) return r end
function PURE.cvs(s) local r = cv(s, "<f", 4) return r end
function PURE.cvd(s) local r = cv(s, "<d", 8) return r end
function PURE.lset(old, s)
  if #s >= #old then return s:sub(1, #old) end
  return s .. string.rep(" ", #old - #s)
end
function PURE.rset(old, s)
  if #s >= #old then return s:sub(1, #old) end
  return string.rep(" ", #old - #s) .. s
end

-- ---- arrays -----------------------------------------------------------------------------
-- Tables prefilled over their bounds; a missing key means a fractional or out-of-range
-- subscript: fractional subscripts are rounded, the others are "Subscript out of range".
local function make_array(bounds, k, default)
  local lo, hi = bounds[k][1], bounds[k][2]
  local mt = { lo = lo, hi = hi }
  function mt.__index(t, i)
    if type(i) == "number" and i == i then
      local r = round_even(i)
      if r ~= i then
        local v = rawget(t, math.tointeger(r) or r)
        if v ~= nil then return v end
      end
    end
    error("Subscript out of range", 2)
  end
  function mt.__newindex(t, i, v)
    if type(i) == "number" and i == i then
      local r = round_even(i)
      r = math.tointeger(r) or r
      if r ~= i and rawget(t, r) ~= nil then rawset(t, r, v) return end
    end
    error("Subscript out of range", 2)
  end
  local t = {}
  mt.default = default
  if k == #bounds then
    -- a function default makes each element afresh (records: one table each)
    if type(default) == "function" then
      for i = lo, hi do t[i] = default() end
    else
      for i = lo, hi do t[i] = default end
    end
  else
    for i = lo, hi do t[i] = make_array(bounds, k + 1, default) end
  end
  return setmetatable(t, mt)
end
local MAX_ELEMENTS = 1 << 24
local function dim(default, level, ...)
  local bounds = {}
  local total = 1
  for i = 1, select("#", ...) do
    local b = select(i, ...)
    local lo, hi
    if type(b) == "table" then lo, hi = b[1], b[2] else lo, hi = 0, b end
    lo, hi = to_int(lo, -32768, 32767, level + 1), to_int(hi, -32768, 32767, level + 1)
    if hi < lo then error("Subscript out of range", level + 1) end
    bounds[i] = { lo, hi }
    -- refused before anything is allocated (DIM a(32767, 32767) is a billion elements)
    total = total * (hi - lo + 1)
    if total > MAX_ELEMENTS then error("Out of memory", level + 1) end
  end
  return make_array(bounds, 1, default)
end
function PURE.dim(...) local a = dim(0, 2, ...) return a end
function PURE.dim_str(...) local a = dim("", 2, ...) return a end

-- ---- fixed-length strings, records, ERASE, STATIC ------------------------------------------
local MAX_STRING = 32767
-- s + t: QBasic's strings have at most 32,767 characters
function PURE.cat(a, b)
  if #a + #b > MAX_STRING then error("String formula too complex", 2) end
  return a .. b
end
-- a store into a STRING * n: padded with spaces or cut to n characters
function PURE.fixstr(v, n)
  if #v >= n then return v:sub(1, n) end
  return v .. string.rep(" ", n - #v)
end
-- a fixed-length string nobody assigned holds NUL bytes, as in QBasic
function PURE.fixed_init(n) return string.rep("\0", n) end
function PURE.dim_fixed(n, ...) local a = dim(string.rep("\0", n), 2, ...) return a end
local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = type(v) == "table" and copy(v) or v end
  return c
end
function PURE.rec_copy(r) return copy(r) end
-- ERASE: every element back to its first value (0, "", NUL bytes, an empty record)
local function erase(t)
  local mt = getmetatable(t)
  if not mt or not mt.lo then error("Type mismatch", 3) end
  for i = mt.lo, mt.hi do
    local v = rawget(t, i)
    if type(v) == "table" and getmetatable(v) and getmetatable(v).lo then erase(v)
    elseif type(mt.default) == "function" then rawset(t, i, mt.default())
    else rawset(t, i, mt.default) end
  end
end
function PURE.erase(t) erase(t) end
-- MID$(s, start, n) = t: the characters from start replaced, the length kept
function PURE.mid_set(s, start, n, t)
  start = long(start, 2)
  if start < 1 or start > #s then error(IFC, 2) end
  local k = #t
  if n ~= nil then
    n = count(n, 2)
    if n < k then k = n end
  end
  if k > #s - start + 1 then k = #s - start + 1 end
  return s:sub(1, start - 1) .. t:sub(1, k) .. s:sub(start + k)
end
local function bound(a, n, which, level)
  n = n and long(n, level + 1) or 1
  local t = a
  for _ = 2, n do
    local mt = getmetatable(t)
    if not mt or not mt.lo then error("Subscript out of range", level + 1) end
    t = rawget(t, mt.lo)
    if type(t) ~= "table" then error("Subscript out of range", level + 1) end
  end
  local mt = getmetatable(t)
  if n < 1 or not mt or not mt.lo then error("Subscript out of range", level + 1) end
  return mt[which]
end
function PURE.lbound(a, n) local r = bound(a, n, "lo", 2) return r end
function PURE.ubound(a, n) local r = bound(a, n, "hi", 2) return r end
-- the drawing statements take SINGLE coordinates
local function coord(x, level)
  x = f32(x)
  if x - x ~= 0 then error("Overflow", level + 1) end
  return x
end

-- ---- the runtime object ---------------------------------------------------------------
-- new(host, chunkname) makes the program's environment E and the runtime's state R: the
-- host's drawing functions, the DATA items and the read position, the TYPE templates, the
-- STATIC names made, the output column, the SCREEN mode and its facts, and R.rt, the link to
-- the screen module (qbasic_screen.lua).  Each install_* below adds one group of E's
-- functions over R.

-- a function of the drawing layer: the host's (pointcalc's globals) or the module's
local function draw(host, name)
  local f = host[name] or pc[name]
  if not f then
    return function() error("the pointcalc drawing layer is not loaded (" .. name .. ")", 3) end
  end
  return f
end

-- records (TYPE ... END TYPE): a table per record, made from its type's template; STATIC
-- arrays, records and fixed strings are made on the first call of their procedure
local function install_records(E, R)
  function E.record(name) return copy(R.types[name]) end
  function E.dim_rec(name, ...)
    local template = R.types[name]
    local a = dim(function() return copy(template) end, 2, ...)
    return a
  end
  function E.static_new(name)
    if R.made[name] then return false end
    R.made[name] = true
    return true
  end
end

local function install_data(E, R)
  -- ---- DATA -------------------------------------------------------------------------------
  local function next_item(level)
    local v = R.data[R.data_pos]
    if v == nil then error("Out of DATA", level + 1) end
    R.data_pos = R.data_pos + 1
    return v, R.data_lines[R.data_pos - 1]
  end
  function E.read_number()
    local v, line = next_item(2)
    if type(v) == "table" then v = v[1] end
    if type(v) ~= "number" then
      -- QBasic reports a non-numeric item against the DATA line
      error(R.chunkname .. ":" .. line .. ": Syntax error", 0)
    end
    if v - v ~= 0 then error("Overflow", 2) end     -- DATA 1D400
    return v
  end
  function E.read_string()
    local v = next_item(2)
    if type(v) == "table" then return v[2] end
    if type(v) == "number" then
      local s = data_text(v, 2)
      return s
    end
    return v
  end
  function E.restore(label)
    if label == nil then R.data_pos = 1 return end
    R.data_pos = R.data_labels[label] or (#R.data + 1)
  end
end

local function install_print(E, R)
  -- ---- PRINT ------------------------------------------------------------------------------
  local ZONE = setmetatable({}, { __name = "zone" })
  local NONL = setmetatable({}, { __name = "nonl" })
  local MARK = {}
  E.zone, E.nonl = ZONE, NONL
  function E.tab(n) return { [MARK] = "tab", n = n } end
  function E.spc(n) return { [MARK] = "spc", n = n } end
  function E.dbl(x) return { [MARK] = "double", v = x } end
  function E.lng(x) return { [MARK] = "long", v = x } end
  -- PRINT's text goes through the screen module: standard output, and the picture on a
  -- graphics screen (qbasic_screen.lua)
  local function write(s)
    R.col = R.rt.text_out(s)
  end
  R.write = write
  -- PRINT's items, through write(s) (which returns the column after it)
  local function print_items(write, col, ...)
    local n = select("#", ...)
    local newline = true
    for i = 1, n do
      local v = select(i, ...)
      local tv = type(v)
      if tv == "string" then
        col = write(v)
      elseif tv == "number" then
        -- SINGLE (and INTEGER, which prints the same); LONG and DOUBLE come marked
        local s = fmt_number(v, "single", 3)
        col = write((v >= 0 and " " or "") .. s .. " ")
      elseif v == ZONE then
        col = write(string.rep(" ", 14 - col % 14))
        if i == n then newline = false end
      elseif v == NONL then
        newline = false
      elseif tv == "table" and v[MARK] then
        local m = v[MARK]
        if m == "tab" then
          local c = long(v.n, 3)
          if c < 1 then c = 1 end
          if col > c - 1 then col = write("\n") end
          col = write(string.rep(" ", c - 1 - col))
        elseif m == "spc" then
          local c = long(v.n, 3)
          if c < 0 then c = 0 end
          col = write(string.rep(" ", c))
        else
          local s = fmt_number(v.v, m, 3)
          col = write((v.v >= 0 and " " or "") .. s .. " ")
        end
      end
    end
    if newline then write("\n") end
  end
  local function screen_write(s) write(s) return R.col end
  function E.qprint(...) print_items(screen_write, R.col, ...) end
  function E.fprint(n, ...)
    print_items(function(s) return R.rt.file_put(n, s, 4) end, R.rt.file_col(n), ...)
  end
  -- WRITE's numbers: PRINT's text without its spaces
  function R.rt.number_text(v)
    if type(v) == "table" then return fmt_number(v.v, v[MARK], 3) end
    return fmt_number(v, "single", 3)
  end
  -- PRINT USING fmt$; values (qbasic_using.lua); a last nonl: no new line
  local using = require("qbasic_using")
  local function using_error(msg) error(msg, 4) end
  local function formatted(fmt, ...)
    local values = { ... }
    local newline = true
    if values[#values] == NONL then values[#values] = nil; newline = false end
    for i, v in ipairs(values) do
      if type(v) == "table" and v[MARK] == "double" then values[i] = { double = v.v } end
    end
    return using.format(fmt, values, using_error) .. (newline and "\n" or "")
  end
  function E.qprint_using(fmt, ...) write(formatted(fmt, ...)) end
  function E.fprint_using(n, fmt, ...) R.rt.file_put(n, formatted(fmt, ...), 2) end
end

local function install_drawing(E, R)
  -- ---- drawing ----------------------------------------------------------------------------
  local h_screen, h_cls, h_color, h_palette = draw(R.host, "screen"), draw(R.host, "cls"), draw(R.host, "color"), draw(R.host, "palette")
  local h_pset, h_preset, h_line, h_line_to = draw(R.host, "pset"), draw(R.host, "preset"), draw(R.host, "line"), draw(R.host, "line_to")
  local h_circle, h_paint, h_point = draw(R.host, "circle"), draw(R.host, "paint"), draw(R.host, "point")
  local h_window, h_view, h_last_point = draw(R.host, "window"), draw(R.host, "view"), draw(R.host, "last_point")
  local function graphics(level)
    if R.mode == 0 then error(IFC, level + 1) end
  end
  -- COLOR's and PALETTE's attribute: one of the mode's
  local function attribute(c, level)
    if c ~= c then error(IFC, level + 1) end
    local r = round_even(c)
    if r < 0 or r >= R.ncolors then error(IFC, level + 1) end
    return math.tointeger(r)
  end
  -- A colour beyond the mode's attributes keeps the bits the video memory has (the planes of
  -- the 16-colour modes, SCREEN 1's 2 bits: 16 is 0, 7 is 3), and SCREEN 2 shows any
  -- colour but 0 as 1 (QuickBASIC 4.x, Microsoft KB Q28026); beyond 0..255 is an error
  local function colour(c, level)
    if c == nil then return nil end
    if c ~= c then error(IFC, level + 1) end
    local r = round_even(c)
    if r < 0 or r > 255 then error(IFC, level + 1) end
    r = math.tointeger(r)
    if R.ncolors == 2 and R.mode == 2 then return r ~= 0 and 1 or 0 end
    return r % R.ncolors
  end

  -- SCREEN mode, colour switch, active page, visual page
  function E.screen(m, _, apage, vpage)
    if m ~= nil then
      m = to_int(m, -32768, 32767, 2)
      if m == 0 then
        R.mode = 0
        R.window_on, R.view_on = false, false
        R.rt.text_mode(nil)
      elseif m == R.mode then
        -- the same mode again (SCREEN 7, , p, 1 - p in an animation loop): no new screen
      elseif m == 1 or m == 2 or m == 7 or m == 8 or m == 9 or m == 11 or m == 12 or m == 13 then
        -- SCREEN 11 is VGA's 640x480 in 2 colours (the drawing layer has no mode 11 of its own)
        if m == 11 then h_screen({ width = 640, height = 480, colors = 2 }) else h_screen(m) end
        R.mode = m
        R.info = R.rt.mode_info(m)
        R.ncolors = R.info.colors
        R.window_on, R.view_on = false, false
        R.rt.dac_reset(m)
        R.rt.text_mode(R.info)
      elseif m == 3 or m == 4 or m == 10 then
        error("SCREEN " .. m .. ": not supported by pointcalc (SCREEN 1, 2, 7, 8, 9, 11, 12 and 13 are)", 2)
      else
        error(IFC, 2)
      end
    end
    if R.mode ~= 0 then R.rt.screen_pages(apage, vpage, 2) end
  end
  function E.cls(n)
    if n ~= nil then
      n = to_int(n, -32768, 32767, 2)
      if n < 0 or n > 2 then error(IFC, 2) end
    end
    R.rt.cls(n)
  end
  function E.color(fg, bg, border)
    if border ~= nil then
      -- the border (overscan) colour: text mode's only, outside the picture
      if R.mode ~= 0 then error(IFC, 2) end
      border = to_int(border, -32768, 32767, 2)
      if border < 0 or border > 15 then error(IFC, 2) end
    end
    if R.mode == 0 then                  -- text colours: the text screen's (qbasic_textscreen.lua)
      if fg ~= nil then fg = to_int(fg, -32768, 32767, 2) if fg < 0 or fg > 31 then error(IFC, 2) end end
      if bg ~= nil then bg = to_int(bg, -32768, 32767, 2) if bg < 0 or bg > 15 then error(IFC, 2) end end
      R.rt.text_color(fg, bg)
      return
    end
    if R.mode ~= 11 and R.mode ~= 12 and R.mode ~= 13 then R.rt.color_other(R.mode, fg, bg, 2) return end
    if bg ~= nil then error(IFC, 2) end
    if fg ~= nil then h_color(attribute(fg, 2)) end
  end
  function E.palette(attr, c)
    if R.mode == 0 then return end
    if attr == nil then h_palette() R.rt.dac_reset(R.mode) return end
    attr = attribute(attr, 2)
    if R.mode ~= 11 and R.mode ~= 12 and R.mode ~= 13 then R.rt.palette_other(R.mode, attr, c, 2) return end
    c = to_int(c, -2147483648, 2147483647, 2)
    if c == -1 then return end
    if c < 0 or c > 0x3F3F3F or (c & 0xC0C0C0) ~= 0 then error(IFC, 2) end
    h_palette(attr, c)
    R.rt.dac_set(R.mode, attr, c)
  end
  -- PALETTE USING a(i): attribute k takes element i + k (-1: unchanged), for every attribute
  function E.palette_using(arr, at)
    if R.mode == 0 then return end
    local mt = getmetatable(arr)
    local first = at[1] and to_int(at[1], -32768, 32767, 2) or mt.lo
    for k = 0, R.ncolors - 1 do
      local v = rawget(arr, first + k)
      if type(v) ~= "number" then error(IFC, 2) end
      E.palette(k, v)
    end
  end
  -- CLEAR: the variables named (the module's) back to 0, "" and undimensioned arrays
  function E.clear(names)
    for _, n in ipairs(names) do rawset(E, n, nil) end
  end
  -- PSET is the statement of drawing loops: the checks of graphics, coord and colour written
  -- out (bench/qbasic), a whole colour within the mode's attributes taken as it is
  local tointeger = math.tointeger
  function E.pset(x, y, c)
    if R.mode == 0 then error(IFC, 2) end
    x, y = f32(x), f32(y)
    if x - x ~= 0 or y - y ~= 0 then error("Overflow", 2) end
    if c ~= nil then
      local k = tointeger(c)
      if not k or k < 0 or k >= R.ncolors or R.mode == 2 then c = colour(c, 2) else c = k end
    end
    h_pset(x, y, c)
  end
  function E.preset(x, y, c)
    graphics(2)
    h_preset(coord(x, 2), coord(y, 2), colour(c, 2))
  end
  -- LINE's style bits (an INTEGER: &HFF00 is -256) go to the drawing layer as 16 bits
  local function bits(p, level)
    if p == nil then return nil end
    return to_int(p, -32768, 65535, level + 1) & 0xFFFF
  end
  function E.line(x1, y1, x2, y2, c, style, pattern)
    graphics(2)
    h_line(coord(x1, 2), coord(y1, 2), coord(x2, 2), coord(y2, 2), colour(c, 2), style,
      bits(pattern, 2))
  end
  function E.line_to(x2, y2, c, style, pattern)
    graphics(2)
    h_line_to(coord(x2, 2), coord(y2, 2), colour(c, 2), style, bits(pattern, 2))
  end
  local TWO_PI = 2 * math.pi + 1e-6
  function E.circle(x, y, r, c, a0, a1, aspect)
    graphics(2)
    r = coord(r, 2)
    if r < 0 then error(IFC, 2) end
    if a0 ~= nil and math.abs(a0) > TWO_PI then error(IFC, 2) end
    if a1 ~= nil and math.abs(a1) > TWO_PI then error(IFC, 2) end
    if aspect ~= nil then
      aspect = coord(aspect, 2)
      if aspect <= 0 then error(IFC, 2) end
    elseif R.mode ~= 12 then
      aspect = R.info.aspect     -- the mode's pixels are not square: circles look round on 4:3
    end
    h_circle(coord(x, 2), coord(y, 2), r, colour(c, 2), a0, a1, aspect)
  end
  function E.paint(x, y, c, border)
    graphics(2)
    if type(c) == "string" then   -- a tile: the pattern's bytes as the mode reads them
      R.rt.paint_tile(coord(x, 2), coord(y, 2), c, colour(border, 2), 2)
      return
    end
    h_paint(coord(x, 2), coord(y, 2), colour(c, 2), colour(border, 2))
  end
  function E.point(x, y)
    graphics(2)
    if y == nil then
      local n = to_int(x, -32768, 32767, 2)
      if n == 2 or n == 3 then
        local lx, ly = h_last_point()
        local r = (n == 2) and lx or ly
        return r
      end
      if n == 0 or n == 1 then
        local r = R.rt.point_physical(n)
        return r
      end
      error(IFC, 2)
    end
    local r = h_point(coord(x, 2), coord(y, 2))
    return r
  end
  function E.window(x1, y1, x2, y2, screen)
    graphics(2)
    if x1 == nil then h_window() R.window_on = false return end
    if x1 == x2 or y1 == y2 then error(IFC, 2) end
    R.window_on = true
    h_window(coord(x1, 2), coord(y1, 2), coord(x2, 2), coord(y2, 2), screen)
  end
  function E.view(x1, y1, x2, y2, fill, border, screen)
    graphics(2)
    if x1 == nil then h_view() R.view_on = false return end
    R.view_on = true
    local w, h = R.info.width, R.info.height
    for _, v in ipairs({ x1, x2 }) do if v < 0 or v >= w then error(IFC, 2) end end
    for _, v in ipairs({ y1, y2 }) do if v < 0 or v >= h then error(IFC, 2) end end
    h_view(x1, y1, x2, y2, colour(fill, 2), colour(border, 2), screen)
  end
  function E.step_xy(dx, dy)
    graphics(2)
    local x, y = h_last_point()
    return x + dx, y + dy
  end
end

-- run(program, info): info.data = {[line] = {items}}, info.data_labels = {label = index},
-- info.strings = {names}, info.arrays = {name = {rank [, "string"]}}, info.base = 1 after
-- OPTION BASE 1
-- CHAIN "prog": the program runs the other one (in its folder, .BAS by default) and ends; the
-- variables of its COMMON go, by position, to the other program's COMMON; the screen stays
local chained = nil     -- what a CHAIN passes to the next runtime: {values, mode}
local function install_chain(E, R)
  function E.common(names)
    R.common = names
    if R.passed then
      for i, n in ipairs(names) do
        if R.passed[i] ~= nil then rawset(E, n, R.passed[i]) end
      end
      R.passed = nil
    end
  end
  function E.run_program(name)
    if name == nil then name = R.chunkname:match("[^/]*$") end
    R.common = nil      -- RUN passes nothing on
    E.chain(name)
  end
  function E.chain(name)
    local dir = files_rt.folder_of(R.chunkname)
    if not name:find("%.[^/\\]*$") then name = name .. ".BAS" end
    local path = files_rt.existing(files_rt.resolve(dir, name, 2))
    if not path then error("File not found", 2) end
    local ok, h = pcall(io.open, path, "rb")
    if not ok then error("Permission denied (" .. tostring(h) .. ")", 2) end
    if not h then error("File not found", 2) end
    local src = h:read("a")
    h:close()
    local shown = path:gsub("^%./", "")
    local lua, msg = require("qbasic").translate(src, shown)
    if not lua then error(setmetatable({ text = msg }, Message), 0) end
    local values = {}
    for i, n in ipairs(R.common or {}) do values[i] = E[n] end
    chained = { values = values, mode = R.mode }
    local chunk = assert(load(lua, "@" .. shown, "t", R.host))
    R.rt.close_all()
    chunk()
    error(STOP, 0)
  end
end

local function install_run(E, R)
  function E.run(program, info)
    info = info or {}
    if info.data then
      local ls = {}
      for l in pairs(info.data) do ls[#ls + 1] = l end
      table.sort(ls)
      for _, l in ipairs(ls) do
        for _, v in ipairs(info.data[l]) do
          R.data[#R.data + 1] = v
          R.data_lines[#R.data] = l
        end
      end
    end
    R.data_labels = info.data_labels or {}
    R.types = info.types or {}
    local strings = {}
    for _, s in ipairs(info.strings or {}) do strings[s] = true end
    local arrays = info.arrays or {}
    setmetatable(E, { __index = function(t, k)
      if strings[k] then return "" end
      local a = arrays[k]
      if a then
        -- an array used without DIM has subscripts 0..10 (1..10 after OPTION BASE 1)
        local b = {}
        for i = 1, a[1] do b[i] = { info.base or 0, 10 } end
        local arr = dim(a[2] == "string" and "" or 0, 1, table.unpack(b))
        rawset(t, k, arr)
        return arr
      end
      return 0
    end })
    qb.seed(327680)
    R.src = dbg and dbg.getinfo(program, "S").short_src
    local ok, err = xpcall(program, qbasic_message_for(R.chunkname, program))
    R.rt.close_all()
    if not ok and err ~= STOP then error(err, 0) end
  end
end

-- ---- error trapping (ON ERROR GOTO, RESUME, ERR, ERL, ERROR n) ----------------------------
-- QBasic's error numbers of its messages (the QBasic 1.1 manual's table)
local ERRORS = { [1] = "NEXT without FOR", [2] = "Syntax error", [3] = "RETURN without GOSUB",
  [4] = "Out of DATA", [5] = "Illegal function call", [6] = "Overflow", [7] = "Out of memory",
  [8] = "Label not defined", [9] = "Subscript out of range", [10] = "Duplicate definition",
  [11] = "Division by zero", [12] = "Illegal in direct mode", [13] = "Type mismatch",
  [14] = "Out of string space", [16] = "String formula too complex", [17] = "Cannot continue",
  [18] = "Function not defined", [19] = "No RESUME", [20] = "RESUME without error",
  [24] = "Device timeout", [25] = "Device fault", [26] = "FOR without NEXT",
  [27] = "Out of paper", [29] = "WHILE without WEND", [30] = "WEND without WHILE",
  [33] = "Duplicate label", [35] = "Subprogram not defined", [37] = "Argument-count mismatch",
  [38] = "Array not defined", [40] = "Variable required", [50] = "FIELD overflow",
  [51] = "Internal error", [52] = "Bad file name or number", [53] = "File not found",
  [54] = "Bad file mode", [55] = "File already open", [56] = "FIELD statement active",
  [57] = "Device I/O error", [58] = "File already exists", [59] = "Bad record length",
  [61] = "Disk full", [62] = "Input past end of file", [63] = "Bad record number",
  [64] = "Bad file name", [67] = "Too many files", [68] = "Device unavailable",
  [69] = "Communication-buffer overflow", [70] = "Permission denied", [71] = "Disk not ready",
  [72] = "Disk-media error", [73] = "Advanced feature unavailable", [74] = "Rename across disks",
  [75] = "Path/File access error", [76] = "Path not found" }
local ERROR_NUMBER = {}
for n, msg in pairs(ERRORS) do ERROR_NUMBER[msg] = n end
M.ERRORS = ERRORS
-- the number of a runtime error: its message without the location and the host's reason in
-- parentheses; nil for what QBasic has no number for (a feature pointcalc lacks, a limit)
local function error_number(e)
  if type(e) ~= "string" then return nil end
  local msg = e:gsub("^[^\n]-:%d+: ", "")
  if msg:find("stack overflow", 1, true) then return 28 end     -- Out of stack space
  if msg:find("not enough memory", 1, true) then return 7 end
  msg = msg:gsub(" %(.*$", "")
  return ERROR_NUMBER[msg] or msg:match("^Unprintable error (%d+)$") and tonumber(msg:match("%d+"))
end

local function install_errors(E, R)
  -- R.handler: the handler's subroutine (nil: errors end the program); R.err, R.erl: ERR, ERL
  R.err, R.erl = 0, 0
  function E.on_error(fn)
    if fn == nil and R.in_handler then error(R.error, 0) end   -- ON ERROR GOTO 0 in the handler
    R.handler = fn
  end
  -- a statement of the module: run f; on a trappable error with a handler in force, the handler
  -- runs and says what next (RESUME: f again, RESUME NEXT: on, RESUME label: the label)
  -- (block: f computes a block's condition or bounds, and RESUME NEXT returns "next" for the
  -- code to go past the block; a RESUME label from a GOSUB subroutine comes back as its label)
  function E.trap(f, erl, block)
    while true do
      local ok, e = pcall(f)
      if ok then return nil end
      if type(e) == "table" and e.qb_resume then return e.qb_resume end
      local n = R.handler and not R.in_handler and error_number(e)
      if not n then error(e, 0) end
      R.err, R.erl, R.error, R.in_handler = n, erl, e, true
      local what = R.handler()
      R.in_handler, R.err = false, 0
      if what == nil then error("No RESUME", 2) end
      if what == "next" then return block and "next" or nil end
      if what ~= "retry" then return what end
    end
  end
  function E.resume_ok(what)
    if not R.in_handler then error("RESUME without error", 2) end
    return what
  end
  -- RESUME label from a statement of a GOSUB subroutine: the subroutines end, up to the
  -- module's statement that called the first, which jumps (QBasic's RESUME drops the GOSUBs)
  function E.resume_at(label)
    error({ qb_resume = label }, 0)
  end
  function E.err_() return R.err end
  function E.erl_() return R.erl end
  function E.error_n(n)
    n = to_int(n, -32768, 32767, 2)
    if n < 1 or n > 255 then error(IFC, 2) end
    error(ERRORS[n] or ("Unprintable error " .. n), 2)
  end
end

function M.new(host, chunkname)
  local E = {}
  for k, f in pairs(PURE) do E[k] = f end
  local R = { host = host, chunkname = chunkname, data = {}, data_lines = {}, data_pos = 1,
    data_labels = {}, types = {}, made = {}, col = 0, mode = 0, ncolors = 16, info = nil,
    rt = {} }
  -- mode 0 is text mode (no graphics), as when QBasic starts; col is the 0-based output
  -- column; info the mode's facts (mode_info): size, pages, text cells, aspect
  install_records(E, R)
  install_data(E, R)
  install_print(E, R)
  install_drawing(E, R)
  install_errors(E, R)
  install_chain(E, R)
  function E.stop() error(STOP, 0) end

  -- the screen as a text device, the keyboard and the clock (qbasic_screen.lua)
  local rt = R.rt
  rt.IFC, rt.to_int, rt.f32, rt.chunkname = IFC, to_int, f32, chunkname
  rt.draw = function(name) return draw(host, name) end
  rt.coord = coord
  rt.get_mode = function() return R.mode end
  rt.qwrite = function(s) R.write(s) end
  rt.window_or_view = function() return R.window_on or R.view_on end
  -- the program's line being run (for notes on standard error)
  rt.program_line = function()
    for level = 2, 200 do
      local info = dbg and dbg.getinfo(level, "Sl")
      if not info then break end
      if info.short_src == R.src and info.currentline > 0 then return info.currentline end
    end
  end
  screen_rt.install(E, rt)
  hw_rt.install(E, rt)
  files_rt.install(E, rt)
  if chained then   -- a CHAIN started this program: COMMON's values, and the screen as it is
    R.passed = chained.values
    if chained.mode ~= 0 then
      R.mode, R.info = chained.mode, rt.mode_info(chained.mode)
      R.ncolors = R.info.colors
      rt.dac_reset(R.mode)
      rt.text_mode(R.info)
    end
    chained = nil
  end
  rt.text_mode(nil)
  function E.return_without_gosub() error("RETURN without GOSUB", 2) end
  function E.next_without_for() error("NEXT without FOR", 2) end
  -- the GOSUB stack of a module whose subroutines stay in its code (qbasic_emit's dispatch
  -- mode); as deep as QBasic's stack allows recursion about
  -- (a procedure's GOSUBs use a stack of the call, st)
  local gosubs = {}
  function E.gosub_push(k, st)
    st = st or gosubs
    if #st >= 20000 then error("Out of stack space", 2) end
    st[#st + 1] = k
  end
  function E.gosub_pop(st)
    local k = table.remove(st or gosubs)
    if not k then error("RETURN without GOSUB", 2) end
    return k
  end
  function E.skipped_includes(...)
    local t = { ... }
    for i = 1, #t, 2 do
      io.stderr:write(chunkname .. ":" .. t[i] .. ": $INCLUDE: '" .. t[i + 1] .. "' not read: "
        .. "pointcalc does not include other files (a name the program takes from it is "
        .. "reported where it is used)\n")
    end
  end
  function E.direct_lines(...)
    local t = { ... }
    for i = 1, #t, 2 do
      io.stderr:write(chunkname .. ":" .. t[i] .. ": " .. t[i + 1] .. ": a GW-BASIC direct-mode "
        .. "command typed at the prompt, not part of the program: skipped\n")
    end
  end
  install_run(E, R)
  return E
end

return M
