-- QBasic front end: the one table of QBasic's words, shared by the lexer (which words are
-- reserved), the parser (which are functions, statements, types), the resolve pass (argument
-- and result types) and the emit pass (the runtime helper of each function).
local K = {}

-- QBasic's reserved words.  A reserved word can never name a variable; the ones pointcalc
-- does not implement still lex as keywords, so that using them gives "not supported" rather
-- than a mysterious undefined variable.
K.reserved = {}
for w in ([[
abs absolute access alias and any append as asc atn base beep binary bload bsave byval call
calls case cdbl cdecl chain chdir chr$ cint circle clear clng close cls color com command$ common
const cos csng csrlin cvd cvdmbf cvi cvl cvs cvsmbf data date$ declare def defdbl defint deflng
defsng defstr dim do double draw else elseif end environ environ$ eof eqv erase erdev erdev$ erl err
error exit exp field fileattr files fix for fre freefile function get gosub goto hex$ if imp
inkey$ inp input input$ instr int integer ioctl ioctl$ is key kill lbound lcase$ left$ len let
line list loc locate lock lof log long loop lpos lprint lset ltrim$ mid$ mkd$ mkdir mkdmbf$
mki$ mkl$ mks$ mksmbf$ mod name next not oct$ off on open option or out output paint palette
pcopy peek pen play pmap point poke pos preserve preset print pset put random randomize read redim rem
reset restore resume return right$ rmdir rnd rset rtrim$ run sadd screen seek seg select
setmem sgn shared shell signal sin single sleep sound space$ spc sqr static step stick stop
str$ strig string string$ sub swap system tab tan then time$ timer to troff tron type ubound
ucase$ uevent unlock until using val varptr varptr$ varseg view wait wend while width window write
xor
]]):gmatch("%S+") do K.reserved[w] = true end

-- ---- types ----------------------------------------------------------------------------------
K.TYPE_OF_SUFFIX = { ["%"] = "int", ["&"] = "long", ["!"] = "single", ["#"] = "double",
  ["$"] = "string" }
K.SUFFIX_OF_TYPE = { int = "%", long = "&", single = "!", double = "#", string = "$" }
K.AS_TYPES = { integer = "int", long = "long", single = "single", double = "double",
  string = "string" }
K.NUM_RANK = { int = 1, long = 2, single = 3, double = 4 }
-- the letter a Lua name gets when two variables differ by their suffix only (a, a_s)
K.SFX_NAME = { int = "i", long = "l", single = "f", double = "d", string = "s" }
-- A record (TYPE ... END TYPE) has the type "rec:name"; its key suffix is "@", its name letter r
function K.is_record(ty) return ty ~= nil and ty:sub(1, 4) == "rec:" end
function K.suffix(ty) return K.SUFFIX_OF_TYPE[ty] or "@" end
function K.name_letter(ty) return K.SFX_NAME[ty] or "r" end
-- bytes of an element, for GET's room check and the record sizes of TYPE
K.BYTES = { int = 2, long = 4, single = 4, double = 8 }

-- ---- built-in functions ---------------------------------------------------------------------
-- args: argument types ("n" number, "s" string, "x" either, "arr" an array), a "?" prefix
-- marks optional ones.  ty: the result type, or "arg" (the first argument's), or "float"
-- (SINGLE, DOUBLE for a DOUBLE argument).  lua: the runtime helper, when not the same name.
K.FUNCS = {
  sin = { args = { "n" }, ty = "float" }, cos = { args = { "n" }, ty = "float" },
  tan = { args = { "n" }, ty = "float" }, atn = { args = { "n" }, ty = "float" },
  sqr = { args = { "n" }, ty = "float" }, exp = { args = { "n" }, ty = "float" },
  log = { args = { "n" }, ty = "float" }, abs = { args = { "n" }, ty = "arg" },
  int = { args = { "n" }, ty = "arg" }, fix = { args = { "n" }, ty = "arg" },
  sgn = { args = { "n" }, ty = "int" }, cint = { args = { "n" }, ty = "int" },
  clng = { args = { "n" }, ty = "long" }, csng = { args = { "n" }, ty = "single" },
  cdbl = { args = { "n" }, ty = "double" }, rnd = { args = { "?n" }, ty = "single" },
  timer = { args = {}, ty = "single" },
  len = { args = { "s" }, ty = "long" },
  ["left$"] = { args = { "s", "n" }, ty = "string", lua = "left" },
  ["right$"] = { args = { "s", "n" }, ty = "string", lua = "right" },
  ["mid$"] = { args = { "s", "n", "?n" }, ty = "string", lua = "mid" },
  ["str$"] = { args = { "n" }, ty = "string", lua = "str" },
  val = { args = { "s" }, ty = "double" },
  ["chr$"] = { args = { "n" }, ty = "string", lua = "chr" },
  asc = { args = { "s" }, ty = "int" },
  ["space$"] = { args = { "n" }, ty = "string", lua = "space" },
  ["string$"] = { args = { "n", "x" }, ty = "string", lua = "string_" },
  ["lcase$"] = { args = { "s" }, ty = "string", lua = "lcase" },
  ["ucase$"] = { args = { "s" }, ty = "string", lua = "ucase" },
  ["ltrim$"] = { args = { "s" }, ty = "string", lua = "ltrim" },
  ["rtrim$"] = { args = { "s" }, ty = "string", lua = "rtrim" },
  instr = { args = { "x", "s", "?s" }, ty = "long" },
  ["hex$"] = { args = { "n" }, ty = "string", lua = "hex" },
  ["oct$"] = { args = { "n" }, ty = "string", lua = "oct" },
  point = { args = { "n", "?n" }, ty = "int" },
  -- the screen and the keyboard (docs/qbasic.md, "Programs that expect a person")
  ["inkey$"] = { args = {}, ty = "string", lua = "inkey" },
  ["input$"] = { args = { "n", "?n" }, ty = "string", lua = "input_chars" },
  csrlin = { args = {}, ty = "int" }, pos = { args = { "n" }, ty = "int", lua = "pos_" },
  pmap = { args = { "n", "n" }, ty = "single" },
  ["varptr$"] = { args = { "x" }, ty = "string", lua = "varptr" },
  lbound = { args = { "arr", "?n" }, ty = "long" }, ubound = { args = { "arr", "?n" }, ty = "long" },
  -- the emulated PC (qbasic_hw.lua): ports and memory
  inp = { args = { "n" }, ty = "int" }, peek = { args = { "n" }, ty = "int" },
  -- error trapping: the number of the error being handled and the line number it came from
  err = { args = {}, ty = "int", lua = "err_" }, erl = { args = {}, ty = "long", lua = "erl_" },
  -- numbers as the bytes QBasic stores them (records of random files), and back
  ["mki$"] = { args = { "n" }, ty = "string", lua = "mki" },
  ["mkl$"] = { args = { "n" }, ty = "string", lua = "mkl" },
  ["mks$"] = { args = { "n" }, ty = "string", lua = "mks" },
  ["mkd$"] = { args = { "n" }, ty = "string", lua = "mkd" },
  cvi = { args = { "s" }, ty = "int" }, cvl = { args = { "s" }, ty = "long" },
  cvs = { args = { "s" }, ty = "single" }, cvd = { args = { "s" }, ty = "double" },
  -- the virtual clock and calendar, and an environment with nothing in it
  ["time$"] = { args = {}, ty = "string", lua = "time_s" },
  ["date$"] = { args = {}, ty = "string", lua = "date_s" },
  ["environ$"] = { args = { "x" }, ty = "string", lua = "environ_s" },
  -- files (qbasic_files.lua)
  eof = { args = { "n" }, ty = "int", lua = "eof_" }, lof = { args = { "n" }, ty = "long", lua = "lof_" },
  loc = { args = { "n" }, ty = "long", lua = "loc_" }, freefile = { args = {}, ty = "int" },
  seek = { args = { "n" }, ty = "long", lua = "seek_" },
  screen = { args = { "n", "n", "?n" }, ty = "int", lua = "screen_fn" },
}

-- functions QBasic has and pointcalc does not: named in the error
K.UNSUPPORTED_FUNCS = {}
for w in ([[inkey$ input$ csrlin pos pmap fre varptr
  stick strig pen play sadd lpos
  ioctl$ fileattr varseg varptr$ erdev erdev$ shell command$]]):gmatch("%S+") do
  K.UNSUPPORTED_FUNCS[w] = true
end

-- ---- statements -----------------------------------------------------------------------------
-- Statements the runtime carries out as a call of a helper with these argument types ("n"
-- number, "s" string), the left-out ones nil.
K.RT_STATEMENTS = {
  screen = "nnnn", locate = "nn", width = "nn", draw = "s", pcopy = "nn", sleep = "n",
  beep = "", sound = "nn", play = "s", key_def = "ns", view_print = "nn", randomize_ask = "",
  out_port = "nn", wait_port = "nnn", poke = "nn", def_seg = "n", error_n = "n",
  chain = "s", run_program = "s", bsave = "snn", bload = "sn", set_time = "s", set_date = "s", open_file = "ssnn", seek_file = "nn", kill_file = "s",
  name_file = "ss",
}

-- QBasic's strings are at most 32,767 characters
K.MAX_STRING = 32767

-- statements pointcalc knows but does not implement: named in the error
K.UNSUPPORTED_STMTS = {
  lprint = "LPRINT", on = "ON", shell = "SHELL", files = "FILES", chdir = "CHDIR",
  mkdir = "MKDIR", rmdir = "RMDIR", tron = "TRON", troff = "TROFF",
  ioctl = "IOCTL", lock = "LOCK", unlock = "UNLOCK", reset = "RESET",
  timer = "TIMER ON/OFF", strig = "STRIG", pen = "PEN", com = "COM", signal = "SIGNAL",
  date = "DATE$",
  environ = "ENVIRON", setmem = "SETMEM", absolute = "CALL ABSOLUTE" }

-- Lua's reserved words: no translated name may be one
K.LUA_KEYWORDS = {}
for w in ([[and break do else elseif end false for function goto if in local nil not or
  repeat return then true until while]]):gmatch("%S+") do K.LUA_KEYWORDS[w] = true end

return K
