-- QBasic front end: the text mode's screen (SCREEN 0, where every program starts) kept as
-- QBasic shows it, so a text-mode program written with -o gives its picture.
--
-- Standard output stays the transcript it always was (no wrapping, docs/qbasic.md); beside it
-- this module keeps the 80x25 (or 40-column, 43- and 50-line) grid of characters and colour
-- attributes with its own cursor, which wraps at the right edge and scrolls the text viewport
-- as QBasic's does.  When the picture is written (interp/main.c calls qbasic_screen.TEXT_PICTURE)
-- the grid is drawn into a canvas of 8-pixel cells: the VGA 8x16 font at 25 lines (640x400
-- for 80 columns), the 8x8 font at 43 lines (640x350) and 50 lines (640x400).
local M = {}

-- install(rt, tx): tx is the text screen's layout and transcript cursor (qbasic_screen.lua).
-- Returns the text screen T with its operations.
function M.install(rt, tx)
  local T = { fg = 7, bg = 0, row = 1, col = 1, used = false, ch = {}, at = {} }

  local function clear_rows(top, bottom)
    for r = top, bottom do
      local ch, at = {}, {}
      for c = 1, tx.cols do ch[c], at[c] = 32, T.fg + 16 * T.bg end
      T.ch[r], T.at[r] = ch, at
    end
  end
  -- a new layout (SCREEN, WIDTH): a blank screen, the cursor home.  Only what is shown after
  -- the last one is the picture: a graphics program that ends with SCREEN 0 keeps its drawing.
  function T.reset()
    T.used = false
    clear_rows(1, tx.rows)
    for r = tx.rows + 1, #T.ch do T.ch[r], T.at[r] = nil, nil end
    T.row, T.col, T.pending = tx.top, 1, false
  end
  -- CLS: the rows top..bottom blank in the background colour (QBasic fills the screen with it)
  function T.clear(top, bottom)
    clear_rows(top, bottom)
    T.row, T.col, T.pending = tx.top, 1, false
    if T.bg ~= 0 then T.used = true end
  end
  function T.locate(row, col)
    T.row, T.col, T.pending = row or T.row, col or T.col, false
  end
  -- COLOR fg, bg in text mode: foreground 0..31 (16..31 blink: drawn steady), background
  -- 0..15 (8..15 show as 0..7, their high bit being the blink bit on a VGA)
  function T.color(fg, bg)
    if fg then T.fg = fg % 16 end
    if bg then T.bg = bg % 8 end
  end

  local function newline()
    T.col, T.pending = 1, false
    if T.row < tx.bottom then T.row = T.row + 1 return end
    for r = tx.top, tx.bottom - 1 do T.ch[r], T.at[r] = T.ch[r + 1], T.at[r + 1] end
    clear_rows(tx.bottom, tx.bottom)
  end
  -- PRINT's text from the cursor.  A line that fills the last column leaves the cursor waiting
  -- there: the next character wraps, a newline only ends the line (no empty line between).
  function T.write(s)
    T.used = true
    for i = 1, #s do
      local b = s:byte(i)
      if b == 10 then
        newline()
      else
        if T.pending then newline() end
        if b == 0 then b = 32 end   -- CHR$(0) is a blank cell, as on QBasic's screen
        T.ch[T.row][T.col], T.at[T.row][T.col] = b, T.fg + 16 * T.bg
        if T.col < tx.cols then T.col = T.col + 1 else T.pending = true end
      end
    end
  end

  -- the picture: a canvas of the text screen's size, each run of cells of one attribute drawn
  -- with print_at (blank runs on black are the canvas itself)
  function T.picture()
    if not T.used then return end
    local cell = tx.rows == 25 and 16 or 8
    -- 43 lines are the EGA's 350 scan lines in 8-line cells (the last 6 lines stay black)
    local height = tx.rows == 43 and 350 or tx.rows * cell
    rt.draw("screen")({ width = tx.cols * 8, height = height, colors = 16 })
    local print_at = rt.draw("print_at")
    for r = 1, tx.rows do
      local ch, at = T.ch[r], T.at[r]
      local c = 1
      while c <= tx.cols do
        local a, c2 = at[c], c
        while c2 < tx.cols and at[c2 + 1] == a do c2 = c2 + 1 end
        local run = string.char(table.unpack(ch, c, c2))
        if a >= 16 or run:find("[^ ]") then print_at(r, c, run, a % 16, a // 16, cell) end
        c = c2 + 1
      end
    end
  end
  T.reset()
  return T
end

return M
