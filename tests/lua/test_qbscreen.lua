-- QBasic's screen from Lua (l_qbscreen.c): PAINT with a tile string as each mode reads it, and
-- DRAW turning a figure on the monitor (SCREEN 2's pixels are 2.4 times as high as wide).
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")

-- SCREEN 12: a tile row is 4 bytes, one bit plane each (blue, green, red, intensity)
screen(12)
line(16, 16, 47, 31, 14, "b")
paint_tile(30, 20, "\15\0\240\0" .. "\255\255\255\255", 14)
check.eq(point(17, 18), 4, "screen 12: red where the red plane's bit is set (x mod 8 = 1)")
check.eq(point(20, 18), 1, "screen 12: blue where the blue plane's bit is set (x mod 8 = 4)")
check.eq(point(24, 18), 4, "screen 12: the tile repeats every 8 pixels")
check.eq(point(21, 19), 15, "screen 12: the second row: all planes, white")
check.eq(point(16, 20), 14, "screen 12: the border stays")
check.eq(point(50, 20), 0, "screen 12: outside the border: untouched")

-- SCREEN 1: a byte is four 2-bit pixels; without a border the fill stops at the foreground
screen(1)
paint_tile(5, 5, string.char(0x1B))
check.eq(point(0, 0), 0, "screen 1: bits 7-6 = 0")
check.eq(point(5, 3), 1, "screen 1: x mod 4 = 1: bits 5-4 = 1")
check.eq(point(318, 199), 2, "screen 1: x mod 4 = 2")
check.eq(point(319, 0), 3, "screen 1: x mod 4 = 3")

-- SCREEN 2: DRAW's quarter turn keeps the size: A1 R24 goes up 24 * 0.4167 = 10 pixels
screen(2)
draw("BM100,100 C1 A1 R24 A0")
check.eq(point(100, 90), 1, "screen 2: A1 R24 ends 10 pixels up")
check.eq(point(100, 89), 0, "screen 2: and no further")
draw("BM300,100 A1 U10 A0")
check.eq(point(276, 100), 1, "screen 2: A1 U10 goes 24 pixels left")
check.eq(point(275, 100), 0, "screen 2: and no further")
-- SCREEN 8: SCREEN 2's 640x200 in 16 colours on 4 pages, so the same tall pixels
local m8 = mode_info(8)
check.eq(m8.width * 1000 + m8.height, 640200, "screen 8: 640x200")
check.eq(m8.colors * 10 + m8.pages, 164, "screen 8: 16 colours, 4 pages")
check.eq(m8.cols * 100 + m8.rows, 8025, "screen 8: 80x25 text")
screen(8)
draw("BM100,100 C9 A1 R24 A0")
check.eq(point(100, 90), 9, "screen 8: A1 R24 ends 10 pixels up, in colour 9")
check.eq(point(100, 89), 0, "screen 8: and no further")
check.eq(point(639, 199), 0, "screen 8: the last pixel is on the screen")
check.eq(point(640, 0), -1, "screen 8: x = 640 is off it")
-- SCREEN 12's pixels are square: no correction
screen(12)
draw("BM100,100 C2 A1 R10 A0")
check.eq(point(100, 90), 2, "screen 12: A1 R10 goes up 10 pixels")

-- errors name the argument
check.err(function() paint_tile(1, 1, "") end, "argument #3 (tile) must be a string of 1..64 bytes", "empty tile")
check.err(function() paint_tile(1, 1, string.rep("x", 65)) end, "a string of 1..64 bytes", "long tile")
check.err(function() paint_tile(1, 1, 7) end, "(tile) must be a string", "a number as tile")
check.err(function() paint_tile(1, 1, "ab", 16) end, "argument #4 (border) must be a colour number 0..15", "border")
check.err(function() paint_tile("x", 1, "ab") end, "argument #1", "a bad point")

-- print_at's cell height: the text mode's 43 and 50 lines use the 8x8 font on a canvas of any
-- size; the full block CHR$(219) fills its cell exactly
screen{width = 640, height = 400, colors = 16}
print_at(50, 1, "\219", 7, 0, 8)
check.eq(point(0, 392), 7, "cell 8: row 50 starts at y 392")
check.eq(point(7, 399), 7, "cell 8: the block's last pixel")
check.eq(point(0, 391), 0, "cell 8: row 49 untouched")
print_at(1, 2, "\219", 14, 0)
check.eq(point(8, 15), 14, "no cell height: 16 on a 640x400 canvas")
check.err(function() print_at(1, 1, "x", 7, 0, 12) end, "8, 14 or 16", "cell height 12")
check.err(function() print_at(1, 1, "x", 7, 0, 20) end, "argument #6", "cell height 20")
check.done()
