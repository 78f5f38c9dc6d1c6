-- QBasic front end, runtime part 2: the screen as a text device and the keyboard.
--
-- install(E, rt) adds to a program's environment E the statements and functions of programs
-- written for a person at a PC: PRINT's text drawn into the picture on a graphics screen
-- (LOCATE, CSRLIN, POS, VIEW PRINT, WIDTH, CLS 2), the other screen modes with their palettes
-- and pages (SCREEN m, , apage, vpage; PCOPY), DRAW with VARPTR$, GET/PUT, PMAP, and the
-- keyboard and the clock (INKEY$, INPUT, LINE INPUT, INPUT$, SLEEP, TIMER, SOUND, PLAY, BEEP,
-- RANDOMIZE without a seed).  The rules for a run nobody watches are in docs/qbasic.md:
-- input comes from standard input, a virtual clock makes delay loops finish at once and the
-- same way every run, and "press any key" is answered when the input has run out.
--
-- rt: the runtime's shared pieces: draw(name), to_int, f32, fmt_number, IFC, and the state
-- functions get_mode/set_mode.
local M = {}

-- QBasic's TIMER ticks 18.2 times a second; the virtual clock moves one tick per TIMER read
M.TICK = 1 / 18.2
-- INKEY$ with no input left: this many empty polls, then Enter (a "press any key" loop ends)
M.EMPTY_POLLS = 50
-- ... and after this many more polls without a key the program is ended, as a person would
M.GIVE_UP_POLLS = 200000

-- the names this module adds: the translator keeps user names clear of them
M.names = { "locate", "width", "draw", "pcopy", "sleep", "beep", "sound", "play", "key_def",
  "view_print", "get_into", "put_from", "input_fields", "line_input", "randomize_ask", "inkey",
  "input_chars", "csrlin", "pos_", "pmap", "varptr", "text_out", "time_s", "date_s",
  "environ_s", "set_time", "set_date", "screen_fn" }

-- EGA's 64 colours: bits 0-2 blue, green, red at 2/3, bits 3-5 at 1/3 (PALETTE in SCREEN 9)
local function ega64(c)
  local function level(hi, lo) return (((c >> hi) & 1) * 2 + ((c >> lo) & 1)) * 0x55 end
  return string.format("#%02x%02x%02x", level(2, 5), level(1, 4), level(0, 3))
end
-- the 16 colours of the 16-colour modes as EGA colour numbers (brown is 20, not 6)
local EGA16 = { [0] = 0, 1, 2, 3, 4, 5, 20, 7, 56, 57, 58, 59, 60, 61, 62, 63 }

local IFC = "Illegal function call"

-- a host call whose error is QBasic's Illegal function call at the program's line, with the
-- host's reason in parentheses
local function host(level, f, ...)
  local ok, a, b = pcall(f, ...)
  if not ok then error(IFC .. " (" .. tostring(a):gsub("^[^:]*:%d+: ", "") .. ")", level + 1) end
  return a, b
end
local function graphics(rt) return rt.get_mode() ~= 0 end

-- Each install_* adds one group of statements over the screen state S (S.tx: the text
-- screen's cursor, viewport and pages; S.clock: the virtual clock) and rt, the runtime's link.
-- ---- the text screen ------------------------------------------------------------------
local function install_text(E, rt, S)
  local IFC, to_int, draw = rt.IFC, rt.to_int, rt.draw
  local h_print_at, h_scroll, h_cls = draw("print_at"), draw("scroll_text"), draw("cls")
  local tx = S.tx
  local out = io.stdout
  -- the characters on the screen, for the SCREEN(row, col) function: cells[row][col] = byte
  local cells = {}
  S.cells = cells
  local function remember(row, col, part)
    local r = cells[row] or {}
    cells[row] = r
    for i = 1, #part do
      if col + i - 1 <= tx.cols then r[col + i - 1] = part:byte(i) end
    end
  end
  local function scroll_cells()
    for r = tx.top, tx.bottom - 1 do cells[r] = cells[r + 1] end
    cells[tx.bottom] = nil
  end
  local function forget(top, bottom) for r = top, bottom do cells[r] = nil end end
  -- text mode's screen as QBasic shows it, for the picture (qbasic_textscreen.lua)
  local TS = require("qbasic_textscreen").install(rt, tx)
  S.tscreen = TS
  function M.TEXT_PICTURE() if not graphics(rt) then TS.picture() end end
  function rt.text_color(fg, bg) TS.color(fg, bg) end
  function E.screen_fn(row, col, flag)
    row, col = to_int(row, -32768, 32767, 2), to_int(col, -32768, 32767, 2)
    if row < 1 or row > tx.rows or col < 1 or col > tx.cols then error(IFC, 2) end
    if flag ~= nil and to_int(flag, -32768, 32767, 2) ~= 0 then
      return graphics(rt) and (draw("color")()) or 7   -- the attribute: the text colour
    end
    return cells[row] and cells[row][col] or 32
  end

  local function newline()
    tx.col = 1
    if tx.row < tx.bottom then
      tx.row = tx.row + 1
    else
      scroll_cells()
      if graphics(rt) then h_scroll(tx.top, tx.bottom, 0) end
    end
  end

  -- text on the screen from the cursor: cells of the picture on a graphics screen, wrapping
  -- at the right edge and scrolling the text viewport as QBasic does
  local function screen_text(s)
    local i = 1
    while i <= #s do
      local nl = s:find("\n", i, true)
      local piece = s:sub(i, (nl or #s + 1) - 1)
      while #piece > 0 do
        local room = tx.cols - tx.col + 1
        local part = piece:sub(1, room)
        -- CHR$(0) shows as a blank cell on QBasic's screen (code page 437's glyph 0 is none)
        h_print_at(tx.row, tx.col, (part:gsub("%z", " ")), nil, 0)
        remember(tx.row, tx.col, part)
        tx.col = tx.col + #part
        piece = piece:sub(room + 1)
        if tx.col > tx.cols then newline() end
      end
      if nl then newline() i = nl + 1 else break end
    end
  end

  -- all PRINT output: standard output always (a transcript of the run), and the picture on
  -- a graphics screen.  Returns the 0-based column after it, for zones and TAB.
  function rt.text_out(s)
    out:write(s)
    -- CHR$(7), the bell: QBasic beeps and the screen keeps no cell of it
    if s:find("\7", 1, true) then s = s:gsub("\7", "") end
    if graphics(rt) then
      screen_text(s)
    else   -- text mode: standard output is the transcript; no wrapping (docs/qbasic.md)
      TS.write(s)
      local row, col = tx.row, tx.col
      for line, sep in s:gmatch("([^\n]*)(\n?)") do
        remember(row, col, line)
        if sep == "" then break end
        row, col = math.min(row + 1, tx.bottom), 1
      end
      local nl = s:find("\n[^\n]*$")
      if nl then
        local _, n = s:gsub("\n", "")
        tx.row = math.min(tx.row + n, tx.bottom)
        tx.col = #s - nl + 1
      else
        tx.col = tx.col + #s
      end
    end
    return tx.col - 1
  end
  function rt.text_col() return tx.col - 1 end

  function rt.text_mode(info)   -- SCREEN: the text screen of the new mode, cursor home
    tx.rows, tx.cols = info and info.rows or 25, info and info.cols or 80
    tx.top, tx.bottom, tx.row, tx.col = 1, tx.rows, 1, 1
    tx.pages, tx.active, tx.visual = info and info.pages or 1, 0, 0
    forget(1, 60)
    TS.reset()
  end

  function E.locate(row, col)
    if row ~= nil then
      row = to_int(row, -32768, 32767, 2)
      if row < 1 or row > tx.rows then error(IFC, 2) end
      -- the transcript on standard output starts a new line where the screen's cursor leaves one
      if row ~= tx.row and tx.col > 1 then out:write("\n") end
      tx.row = row
    end
    if col ~= nil then
      col = to_int(col, -32768, 32767, 2)
      if col < 1 or col > tx.cols then error(IFC, 2) end
      tx.col = col
    end
    TS.locate(row, col)
  end
  function E.csrlin() return tx.row end
  function E.pos_(_) return tx.col end
  function E.view_print(top, bottom)
    if top == nil then
      tx.top, tx.bottom = 1, tx.rows
    else
      top, bottom = to_int(top, -32768, 32767, 2), to_int(bottom, -32768, 32767, 2)
      if top < 1 or bottom > tx.rows or top > bottom then error(IFC, 2) end
      tx.top, tx.bottom = top, bottom
    end
    tx.row, tx.col = tx.top, 1
    TS.locate(tx.row, 1)
  end
  -- WIDTH columns, rows: accepted when QBasic has the size; in text mode the screen takes that
  -- layout (40 or 80 columns, 25, 43 or 50 lines) and is cleared, a graphics mode's stays
  function E.width(cols, rows)
    if cols ~= nil then
      cols = to_int(cols, -32768, 32767, 2)
      if cols ~= 40 and cols ~= 80 then error(IFC, 2) end
    end
    if rows ~= nil then
      rows = to_int(rows, -32768, 32767, 2)
      if rows ~= 25 and rows ~= 30 and rows ~= 43 and rows ~= 50 and rows ~= 60 then error(IFC, 2) end
      -- VGA text mode has 25, 43 and 50 lines (30 and 60 are graphics modes' heights)
      if not graphics(rt) and rows ~= 25 and rows ~= 43 and rows ~= 50 then error(IFC, 2) end
    end
    if not graphics(rt) and ((cols and cols ~= tx.cols) or (rows and rows ~= tx.rows)) then
      tx.cols, tx.rows = cols or tx.cols, rows or tx.rows
      tx.top, tx.bottom, tx.row, tx.col = 1, tx.rows, 1, 1
      forget(1, 60)
      TS.reset()
    end
  end
  -- CLS 0 (or none): the whole screen; 1: the graphics view; 2: the text viewport
  function rt.cls(n)
    if n ~= 1 then forget(n == 2 and tx.top or 1, n == 2 and tx.bottom or tx.rows) end
    if not graphics(rt) then
      tx.row, tx.col = tx.top, 1
      if n == 2 then TS.clear(tx.top, tx.bottom) else TS.clear(1, tx.rows) end
      return
    end
    if n == 2 then
      for r = tx.top, tx.bottom do h_print_at(r, 1, string.rep(" ", tx.cols), nil, 0) end
    elseif n == 1 then
      h_cls()
      return
    else
      h_cls()
    end
    tx.row, tx.col = tx.top, 1
  end
end

local function install_modes(E, rt, S)
  local IFC, to_int, draw = rt.IFC, rt.to_int, rt.draw
  local h_pages, h_pcopy, h_mode_info = draw("pages"), draw("pcopy"), draw("mode_info")
  local h_palette, h_color = draw("palette"), draw("color")
  local tx = S.tx
  -- ---- modes, palettes, pages -----------------------------------------------------------
  function rt.screen_pages(apage, vpage, level)
    if apage == nil and vpage == nil then return end
    local a = apage ~= nil and to_int(apage, -32768, 32767, level + 1) or tx.active
    local v = vpage ~= nil and to_int(vpage, -32768, 32767, level + 1) or tx.visual
    if a < 0 or a >= tx.pages or v < 0 or v >= tx.pages then error(IFC, level + 1) end
    h_pages(a, v)
    tx.active, tx.visual = a, v
  end
  function rt.mode_info(m)
    if m == 11 then   -- VGA's 2-colour mode: SCREEN 12's layout
      return { width = 640, height = 480, colors = 2, pages = 1, cols = 80, rows = 30, cell = 16,
        aspect = 1 }
    end
    return h_mode_info(m)
  end

  function E.pcopy(from, to)
    from, to = to_int(from, -32768, 32767, 2), to_int(to, -32768, 32767, 2)
    if not graphics(rt) then return end
    if from < 0 or from >= tx.pages or to < 0 or to >= tx.pages then error(IFC, 2) end
    host(2, h_pcopy, from, to)
  end

  -- COLOR in the modes where it is not SCREEN 12's: 7 and 9 take a background colour (the
  -- colour shown for attribute 0), SCREEN 1 a background and one of its two palettes
  function rt.color_other(m, fg, bg, level)
    if m == 1 then
      if fg ~= nil then
        fg = to_int(fg, -32768, 32767, level + 1)
        if fg < 0 or fg > 15 then error(IFC, level + 1) end
        h_palette(0, ega64(EGA16[fg]))
      end
      if bg ~= nil then
        bg = to_int(bg, -32768, 32767, level + 1)
        local set = (bg % 2 == 0) and { 10, 12, 14 } or { 11, 13, 15 }
        for i = 1, 3 do h_palette(i, ega64(EGA16[set[i]])) end
      end
      return
    end
    if m == 2 then error(IFC, level + 1) end
    if fg ~= nil then
      fg = to_int(fg, -32768, 32767, level + 1)
      if fg < 0 or fg > 15 then error(IFC, level + 1) end
      h_color(fg)
    end
    if bg ~= nil then
      bg = to_int(bg, -32768, 32767, level + 1)
      if bg < 0 or bg > 15 then error(IFC, level + 1) end
      h_palette(0, ega64(EGA16[bg]))
    end
  end
  -- PALETTE attr, colour in the EGA modes: colour numbers, not VGA's 6-bit mixtures
  function rt.palette_other(m, attr, c, level)
    c = to_int(c, -2147483648, 2147483647, level + 1)
    if c == -1 then return end
    local max = (m == 9) and 63 or 15
    if c < 0 or c > max then error(IFC, level + 1) end
    h_palette(attr, ega64(m == 9 and c or EGA16[c]))
  end
end

local function install_draw(E, rt)
  local IFC, to_int, draw = rt.IFC, rt.to_int, rt.draw
  local h_draw, h_get, h_put, h_pmap = draw("draw"), draw("get_block"), draw("put_block"), draw("pmap")
  local h_last_point = draw("last_point")
  -- ---- DRAW -----------------------------------------------------------------------------
  -- VARPTR$(v) stands for the variable in a DRAW (or PLAY) string: here its value, between
  -- markers that DRAW replaces ("X" + VARPTR$(a$) runs a$, "=" + VARPTR$(n) is n)
  function E.varptr(v)
    if type(v) == "string" then return "\1" .. v .. "\2" end
    return "\1" .. string.format("%d", to_int(v, -32768, 32767, 2)) .. "\2"
  end
  local function expand(s, depth, level)
    if depth > 20 then error(IFC, level + 1) end
    s = s:gsub("[Xx]%s*\1([^\2]*)\2", function(sub) return " " .. expand(sub, depth + 1, level + 1) .. " " end)
    s = s:gsub("=%s*\1([^\2]*)\2", function(n) return n end)
    if s:find("[\1\2=]") then error(IFC, level + 1) end   -- X or = without VARPTR$
    return s
  end
  -- PAINT (x, y), tile$[, border]: 1..64 bytes of pattern (Illegal function call otherwise)
  local h_paint_tile = draw("paint_tile")
  function rt.paint_tile(x, y, tile, border, level)
    if #tile < 1 or #tile > 64 then error(IFC, level + 1) end
    host(level + 1, h_paint_tile, x, y, tile, border)
  end

  function E.draw(s)
    if not graphics(rt) then error(IFC, 2) end
    host(2, h_draw, expand(s, 0, 2))
  end

  -- ---- GET and PUT ----------------------------------------------------------------------
  -- a block is kept beside its array, under the element it was stored at; the array must
  -- have room for the bytes QBasic would store there
  local blocks = setmetatable({}, { __mode = "k" })
  local function key_of(at)
    local t = {}
    for i, v in ipairs(at) do t[i] = string.format("%d", to_int(v, -32768, 32767, 4)) end
    return table.concat(t, ",")
  end
  local function room(arr, at, elem, level)
    -- the elements from `at` to the end of the array (QBasic stores the block there)
    local mt = getmetatable(arr)
    if not mt or not mt.lo then error(IFC, level + 1) end
    local first = at[1] and to_int(at[1], -32768, 32767, level + 1) or mt.lo
    if first < mt.lo or first > mt.hi then error("Subscript out of range", level + 1) end
    local n = mt.hi - first + 1
    local inner = rawget(arr, mt.lo)
    while type(inner) == "table" do   -- further dimensions: whole rows of elements
      local imt = getmetatable(inner)
      n = n * (imt.hi - imt.lo + 1)
      inner = rawget(inner, imt.lo)
    end
    return n * elem
  end
  function E.get_into(x1, y1, x2, y2, arr, at, elem)
    if not graphics(rt) then error(IFC, 2) end
    local b = host(2, h_get, rt.coord(x1, 2), rt.coord(y1, 2), rt.coord(x2, 2), rt.coord(y2, 2))
    if room(arr, at, elem or 2, 2) < b.bytes then error(IFC, 2) end
    blocks[arr] = blocks[arr] or {}
    blocks[arr][key_of(at)] = b
  end
  function E.put_from(x, y, arr, at, action)
    if not graphics(rt) then error(IFC, 2) end
    local b = blocks[arr] and blocks[arr][key_of(at)]
    if not b then error(IFC .. " (PUT of an array element no GET stored a block in)", 2) end
    host(2, h_put, rt.coord(x, 2), rt.coord(y, 2), b, action)
  end

  function E.pmap(v, n)
    if not graphics(rt) then error(IFC, 2) end
    n = to_int(n, -32768, 32767, 2)
    if n < 0 or n > 3 then error(IFC, 2) end
    local r = host(2, h_pmap, v, n)
    return r
  end
  -- POINT(0), POINT(1): the graphics cursor in view pixels
  function rt.point_physical(n)
    local x, y = h_last_point()
    local r = h_pmap(n == 0 and x or y, n)
    return r
  end
end

local function install_clock(E, rt, S)
  -- TIME$ and DATE$: the virtual clock (TIMER's seconds since midnight) and a settable date
  function E.time_s()
    local t = math.floor(S.clock) % 86400
    return string.format("%02d:%02d:%02d", t // 3600, t // 60 % 60, t % 60)
  end
  function E.set_time(s)
    local h, m, sec = s:match("^%s*(%d%d?):?(%d?%d?):?(%d?%d?)%s*$")
    h, m, sec = tonumber(h), tonumber(m) or 0, tonumber(sec) or 0
    if not h or h > 23 or m > 59 or sec > 59 then error(IFC, 2) end
    S.clock = h * 3600 + m * 60 + sec
  end
  S.date = "01-01-1980"
  function E.date_s() return S.date end
  function E.set_date(s)
    local mo, d, y = s:match("^%s*(%d%d?)[-/](%d%d?)[-/](%d+)%s*$")
    mo, d, y = tonumber(mo), tonumber(d), tonumber(y)
    if y and y < 100 then y = y + 1900 end
    if not mo or mo < 1 or mo > 12 or d < 1 or d > 31 or y < 1980 or y > 2099 then error(IFC, 2) end
    S.date = string.format("%02d-%02d-%04d", mo, d, y)
  end
  -- ENVIRON$: a run sees no environment variables (the same every run, and nothing leaks)
  function E.environ_s(_) return "" end
  rt.clock = function() return S.clock end
  -- every step of the virtual clock: with --for SECONDS (M.RUN_FOR), a program still running
  -- after that long on it is ended there, normally: its picture is the screen as it stands
  -- with --frames (M.FRAME, a host function), frame k is taken when the clock passes (k + 1)
  -- times M.FRAME_DT; it says when the last one is taken, and the program is ended there
  local elapsed, frames = 0, 0
  local function advance(dt)
    S.clock = S.clock + dt
    elapsed = elapsed + dt
    while M.FRAME and elapsed >= (frames + 1) * M.FRAME_DT - 1e-9 do
      frames = frames + 1
      if M.FRAME() then
        io.stderr:write(string.format("%s:%s: %d frames taken (--frames): stopped\n",
          rt.chunkname, rt.program_line() or "?", frames))
        E.stop()
      end
    end
    if M.RUN_FOR and elapsed >= M.RUN_FOR then
      io.stderr:write(string.format("%s:%s: ran for %g virtual seconds (--for): stopped; the "
        .. "picture is the screen as it stands\n", rt.chunkname, rt.program_line() or "?", M.RUN_FOR))
      E.stop()
    end
  end
  rt.advance = advance
  local IFC, to_int, draw = rt.IFC, rt.to_int, rt.draw
  -- ---- the clock ------------------------------------------------------------------------
  function E.timer()
    local t = S.clock
    advance(M.TICK)
    return rt.f32(t)
  end
  function E.sleep(n)
    if n ~= nil then
      n = to_int(n, -2147483648, 2147483647, 2)
      if n > 0 then advance(n) end
    end
  end
  function E.beep() end
  function E.sound(freq, ticks)
    if freq - freq ~= 0 or ticks - ticks ~= 0 then error(IFC, 2) end
    if (freq ~= 0 and (freq < 37 or freq > 32767)) or ticks < 0 or ticks > 65535 then error(IFC, 2) end
    advance(ticks * M.TICK)
  end
  function E.play(_) end
  function E.key_def(n, _)
    n = to_int(n, -32768, 32767, 2)
    if n < 1 or n > 31 then error(IFC, 2) end
  end
end

-- --input's names of the keys that are no character, delivered as one INKEY$ key
local KEY_NAMES = { UP = "\0H", DOWN = "\0P", LEFT = "\0K", RIGHT = "\0M", HOME = "\0G",
  END = "\0O", PGUP = "\0I", PGDN = "\0Q", INS = "\0R", DEL = "\0S", F1 = "\0;", F2 = "\0<",
  F3 = "\0=", F4 = "\0>", F5 = "\0?", F6 = "\0@", F7 = "\0A", F8 = "\0B", F9 = "\0C",
  F10 = "\0D", F11 = "\0\133", F12 = "\0\134", ESC = "\27", ENTER = "\r", TAB = "\t",
  BKSP = "\8" }

local function install_keyboard(E, rt, S)
  local IFC, to_int, draw = rt.IFC, rt.to_int, rt.draw
  -- ---- the keyboard ---------------------------------------------------------------------
  local input = io.stdin
  local pending = ""         -- characters of standard input not yet taken
  local at_eof = false
  local empty_polls, total_empty = 0, 0
  local function fill()
    if pending == "" and not at_eof then
      local l = input:read("L")
      if l then pending = l else at_eof = true end
    end
  end
  local function read_line()
    if pending == "" then fill() end
    if pending == "" then return nil end
    local l = pending:gsub("\r?\n$", "")
    pending = ""
    return l
  end
  -- the next key of the input: a character (Enter is CHR$(13)), an extended key as
  -- CHR$(0) + its code (the bytes 0 and the code, or a name in braces: {RIGHT}, {F1}), or nil
  local function take_key()
    fill()
    if pending == "" then return nil end
    local name = pending:match("^{(%u+%d*)}")
    local k
    if name and KEY_NAMES[name] then
      k, pending = KEY_NAMES[name], pending:sub(#name + 3)
    elseif pending:byte(1) == 0 and #pending >= 2 then
      k, pending = pending:sub(1, 2), pending:sub(3)
    else
      k, pending = pending:sub(1, 1), pending:sub(2)
      if k == "\n" then k = "\r" end
    end
    empty_polls, total_empty = 0, 0
    S.last_key = k
    return k
  end
  rt.take_key = take_key
  -- a poll that found no key: a tick of the clock; true when it is time for the Enter that
  -- answers "press any key"; a program still polling long after the input ended is ended
  local function empty_poll()
    rt.advance(M.TICK)
    empty_polls, total_empty = empty_polls + 1, total_empty + 1
    if total_empty > M.GIVE_UP_POLLS then
      io.stderr:write(rt.chunkname .. ": the program keeps waiting for a key and the input has run out: ended\n")
      E.stop()
    end
    if empty_polls > M.EMPTY_POLLS then
      empty_polls = 0
      return true
    end
  end
  rt.empty_poll = empty_poll
  function E.inkey()
    local k = take_key()
    if k then return k end
    if empty_poll() then return "\r" end
    return ""
  end
  -- INPUT, LINE INPUT and INPUT$ with no input left: nobody will answer, so the program ends
  -- there (normally: the picture is written), saying so
  local function input_ended(what)
    io.stderr:write(rt.chunkname .. ":" .. (rt.program_line() or "?") .. ": input ended (" .. what
      .. " with no input left): the program is ended\n")
    E.stop()
  end
  function E.input_chars(n, file)
    if file ~= nil then local r = rt.file_chars(n, file) return r end   -- INPUT$(n, #f)
    n = to_int(n, -32768, 32767, 2)
    if n < 1 or n > 32767 then error(IFC, 2) end
    local t = {}
    for i = 1, n do
      fill()
      if pending == "" then
        if i == 1 then input_ended("INPUT$") end
        t[i] = "\r"
      else
        t[i] = pending:sub(1, 1) == "\n" and "\r" or pending:sub(1, 1)   -- Enter is CHR$(13)
        pending = pending:sub(2)
      end
    end
    return table.concat(t)
  end

  local function echo(prompt, answer, same_line)
    rt.qwrite(prompt .. answer .. (same_line and "" or "\n"))
  end
  function E.line_input(prompt, same_line)
    local l = read_line()
    if not l then
      echo(prompt or "", "", same_line)
      input_ended("LINE INPUT")
    end
    echo(prompt or "", l, same_line)
    return { l }
  end
  -- INPUT: the fields of a line, separated by commas ("quoted" strings keep theirs); a line
  -- with the wrong number of fields or a bad number is QBasic's "Redo from start"; at the end
  -- of the input the variables get 0 and ""
  local function fields(l)
    local t, i = {}, 1
    while true do
      local s = l:match("^%s*", i)
      i = i + #s
      local f
      if l:sub(i, i) == '"' then
        local j = l:find('"', i + 1, true) or #l + 1
        f = l:sub(i + 1, j - 1)
        i = j + 1
        local rest = l:match("^%s*", i)
        i = i + #rest
      else
        local j = l:find(",", i, true) or #l + 1
        f = l:sub(i, j - 1):gsub("%s+$", "")
        i = j
      end
      t[#t + 1] = f
      if l:sub(i, i) == "," then i = i + 1 elseif i > #l then return t else return nil end
    end
  end
  function E.input_fields(prompt, mark, same_line, kinds)
    local p = (prompt or "") .. (mark and "? " or "")
    while true do
      local l = read_line()
      if not l then
        echo(p, "", same_line)
        input_ended("INPUT")
      end
      echo(p, l, same_line)
      local f = fields(l)
      local ok = f and #f == #kinds
      local r = {}
      for i, k in ipairs(kinds) do
        if not ok then break end
        if k == "s" then r[i] = f[i]
        else
          local v = f[i] == "" and 0 or tonumber((f[i]:gsub("[dD]", "e")))
          if not v then ok = false else r[i] = v end
        end
      end
      if ok then return r end
      rt.qwrite("Redo from start\n")
    end
  end
  function E.randomize_ask()
    local l = read_line()
    echo("Random-number seed (-32768 to 32767)? ", l or "", false)
    local n = tonumber(l or "") or 0
    E.randomize(n)
  end
end

function M.install(E, rt)
  local S = { clock = 0, tx = { row = 1, col = 1, top = 1, bottom = 25, rows = 25, cols = 80,
    pages = 1, active = 0, visual = 0 } }
  install_text(E, rt, S)
  install_modes(E, rt, S)
  install_draw(E, rt)
  install_clock(E, rt, S)
  install_keyboard(E, rt, S)
end

return M
