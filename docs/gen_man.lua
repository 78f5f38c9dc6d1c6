-- Write the man page pointcalc(1) from the program's own --help text, so the option table has
-- one source (usage_text in interp/main.c); the build runs this after linking the program:
--   pointcalc docs/gen_man.lua [PATH_TO_POINTCALC] > pointcalc.1
-- The synopsis, OPTIONS and NOTES come from --help; the other sections are written here and say
-- nothing about individual options.
local prog = arg[1] or arg[-1] or "pointcalc"

local function shell_quote(s)
  return "'" .. s:gsub("'", "'\\''") .. "'"
end

local function capture(flag)
  local f = assert(io.popen(shell_quote(prog) .. " " .. flag))
  local text = f:read("a")
  local ok = f:close()
  if not ok or text == "" then
    io.stderr:write("gen_man: '", prog, " ", flag, "' failed\n")
    os.exit(1)
  end
  return text
end

local help, version_line = capture("--help"), capture("-v")
local version = version_line:match("^pointcalc (%S+)") or "unknown"

-- roff text: backslashes, option-like words (a leading hyphen is a minus sign in roff), `code`
local function roff(s)
  s = s:gsub("\\", "\\e")
  s = (" " .. s):gsub("%f[%S]%-", "\\-"):gsub("(\\%-)%-", "%1\\-"):sub(2)
  s = s:gsub("`([^`]+)`", "\\fB%1\\fR")
  if s:match("^[.']") then s = "\\&" .. s end
  return s
end

-- "-h, --help" or "--watch FILE": options bold, their arguments italic
local function term(s)
  return (s:gsub("[^%s,]+", function(w)
    if w:match("^%-") then return "\\fB" .. w:gsub("%-", "\\-") .. "\\fR" end
    return "\\fI" .. w .. "\\fR"
  end))
end

-- Parse --help: the usage line and further forms indented under it ("pointcalc serve ..."), the
-- two-column table (entries indented by two spaces; continuation lines indented past the first
-- column) and the free lines, which become NOTES. Only a help text without a usage line or
-- without any entry fails.
local synopsis, forms, entries, notes = nil, {}, {}, {}
local desc_col, in_table
for line in help:gmatch("[^\n]+") do
  local usage = line:match("^usage: pointcalc%s+(.*)$")
  local form = line:match("^%s+pointcalc%s+(.*)$")
  local lead, name, gap = line:match("^(  )(%S.-)(%s%s+)%S")
  local indent = #line:match("^%s*")
  if usage then
    synopsis = usage
  elseif form then
    local f, what = form:match("^(.-)%s%s+(%S.*)$")
    forms[#forms + 1] = {form = f or form, text = what}
  elseif lead then
    desc_col = #lead + #name + #gap
    entries[#entries + 1] = {name = name, text = line:sub(desc_col + 1)}
    in_table = true
  elseif in_table and indent > 2 and indent >= desc_col - 1 then
    local e = entries[#entries]
    e.text = e.text .. " " .. line:match("^%s*(.-)%s*$")
  else
    notes[#notes + 1] = line
    in_table = false
  end
end
if not synopsis or #entries == 0 then
  io.stderr:write("gen_man: no usage line or option table in '", prog, " --help'\n")
  os.exit(1)
end

-- a synopsis: options bold, placeholders italic, a leading subcommand ("serve") bold
local function synopsis_roff(s, has_command)
  local first = has_command
  return (s:gsub("[%w.=-]+", function(w)
    if w:match("^%-") then first = false; return "\\fB" .. w:gsub("%-", "\\-") .. "\\fR" end
    if first then first = false; return "\\fB" .. w .. "\\fR" end
    return "\\fI" .. w .. "\\fR"
  end))
end

local out = {}
local function put(...)
  for _, s in ipairs({...}) do out[#out + 1] = s end
end

put('.TH POINTCALC 1 "" "pointcalc ', version, '" "User Commands"\n')
put(".SH NAME\n", "pointcalc \\- geometry scripting: point calculus and QBasic-style drawing in Lua\n")
put(".SH SYNOPSIS\n.B pointcalc\n", synopsis_roff(synopsis, false), "\n")
for _, f in ipairs(forms) do
  put(".br\n.B pointcalc\n", synopsis_roff(f.form, not f.form:match("^[%[%-]")), "\n")
end
put(".SH DESCRIPTION\n",
    ".B pointcalc\n",
    "runs geometry scripts written in Lua 5.4, or programs written in QBasic, and writes what they\n",
    "draw as PNG, SVG or PPM.\n",
    "Scripts get point calculus as native types (weighted points and vectors, ratios, meets,\n",
    "simplices, projective maps, one curve type and one surface type) and the drawing statements\n",
    "of QBasic's SCREEN 12 (640\\(mu480, 16 colours, y axis down) with labels, paths and pens.\n",
    "Without a script on a terminal it starts an interactive REPL.\n",
    ".PP\n",
    "The same API is the Lua C module\n",
    ".BR pointcalc.so ,\n",
    "installed where\n",
    ".BR lua5.4 (1)\n",
    "finds it:\n",
    "\\fBlua5.4 \\-e \\(aqpc = require \"pointcalc\"\\(aq\\fR\n",
    "gives every function as a field of\n",
    ".BR pc .\n")

local operands, options = {}, {}
for _, e in ipairs(entries) do
  if e.name:match("^%-") then options[#options + 1] = e else operands[#operands + 1] = e end
end
local function list(title, es)
  if #es == 0 then return end
  put(".SH ", title, "\n")
  for _, e in ipairs(es) do put(".TP\n", term(e.name), "\n", roff(e.text), "\n") end
end
if #forms > 0 then
  put(".SH COMMANDS\n")
  for _, f in ipairs(forms) do
    put(".TP\n\\fBpointcalc\\fR ", synopsis_roff(f.form, not f.form:match("^[%[%-]")), "\n",
        roff(f.text or ""), "\n")
  end
end
list("OPERANDS", operands)
list("OPTIONS", options)
if #notes > 0 then
  put(".SH NOTES\n")
  for _, l in ipairs(notes) do put(roff(l), "\n") end
end

-- the REPL's commands, from the help registry (interp/help.lua), as :help prints them
local registry = require "help"
put(".SH REPL COMMANDS\n",
    "In the REPL, a line is a Lua chunk (an expression's value is printed) or one of these\n",
    "commands; Tab completes names, fields, methods, commands and file names.\n")
for _, e in ipairs(registry.areas.repl.entries) do
  if e.kind == "command" then
    put(".TP\n", term(registry.forms(e)[1]), "\n", roff(e.desc), "\n")
  end
end
put(".SH ENVIRONMENT\n",
    ".TP\n.B HOME\n",
    "the REPL keeps its history in \\fI$HOME/.pointcalc_history\\fR.\n",
    ".TP\n.BR COLUMNS \", \" LINES\n",
    "the size of the terminal, when it cannot be asked (the REPL's \\fB:show\\fR and \\fB:help\\fR).\n",
    ".TP\n.BR NO_COLOR \", \" TERM \", \" COLORTERM\n",
    "whether the REPL colours its output: none with NO_COLOR set or TERM=dumb, 24-bit colour\n",
    "with COLORTERM=truecolor.\n",
    ".TP\n.BR LUA_PATH_5_4 \", \" LUA_PATH \", \" LUA_CPATH_5_4 \", \" LUA_CPATH\n",
    "where \\fBrequire\\fR looks for Lua and C modules, as in\n.BR lua5.4 (1)\n",
    "(end the value with \\fB;;\\fR to keep the default paths); not used in the safe mode.\n",
    ".TP\n.B XDG_DATA_DIRS\n",
    "where bash looks for the completion of\n.BR pointcalc :\n",
    "add \\fIPREFIX\\fR/share for an installation outside /usr and /usr/local.\n")

put(".SH EXIT STATUS\n",
    "0 on success, 1 when a script fails (the message names the file and line, followed by a\n",
    "traceback), 2 on a usage error.\n",
    ".SH FILES\n",
    "Below the installation prefix\n",
    "(\\fI/usr\\fR for the Debian package, \\fI/usr/local\\fR by default):\n",
    ".TP\n.I share/pointcalc/examples\n",
    "the example scripts, one folder per source, and\n",
    ".B render_gallery.sh\n",
    "that renders them all into a browsable page.\n",
    ".TP\n.I share/doc/pointcalc\n",
    "the guides and the API reference (Markdown).\n",
    ".TP\n.I lib/lua/5.4/pointcalc.so\n",
    "the Lua module.\n",
    ".TP\n.IR lib/libpointcalc.so.0 \", \" include/pointcalc/ \", \" lib/pkgconfig/pointcalc.pc\n",
    "the C library, its headers and its pkg-config file\n",
    "(\\fBcc prog.c $(pkg-config \\-\\-cflags \\-\\-libs pointcalc)\\fR).\n",
    ".TP\n.I share/pointcalc/lua-language-server/library\n",
    "definitions for the Lua language server (completion and signatures in editors).\n",
    ".TP\n.I share/jupyter/kernels/pointcalc\n",
    "the Jupyter kernel: one pointcalc per notebook, figures shown inline.\n",
    ".TP\n.I share/pointcalc/install_manifest.txt\n",
    "what \\fB./build.sh install\\fR put under the prefix, for \\fB./build.sh uninstall\\fR.\n",
    ".SH EXAMPLES\n",
    "Render an example to PNG and SVG:\n",
    ".PP\n.RS\n.nf\n",
    "pointcalc /usr/share/pointcalc/examples/stepanov/02_oval_in_quadrilateral.lua \\e\n",
    "    \\-o oval.png \\-o oval.svg\n",
    ".fi\n.RE\n.PP\n",
    "Run one line and keep drawing interactively, with the picture rewritten as it changes:\n",
    ".PP\n.RS\n.nf\n",
    "pointcalc \\-e \\(aqcircle(P(320, 240), 100, 14)\\(aq \\-\\-watch pic.png\n",
    ".fi\n.RE\n",
    ".SH SEE ALSO\n",
    ".BR pointcalc-api (7)\n",
    "(every function with its signature),\n",
    ".BR lua5.4 (1)\n")
io.write(table.concat(out))
