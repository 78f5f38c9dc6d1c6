-- QBasic front end, runtime part 3: the PC hardware a program can see, emulated.
--
-- install(E, rt) adds OUT, INP, WAIT, DEF SEG, PEEK and POKE over a small model of a VGA PC:
--   ports   &H3C7/&H3C8/&H3C9 the VGA DAC (the palette: writes change every written picture,
--           reads give it back), &H3DA the retrace status (WAIT &H3DA, 8 is a tick of the
--           virtual clock), &H60 the keyboard's last scan code (the next key of the input)
--   memory  &HA000:0 the pixels of SCREEN 13 (offset y * 320 + x), the BIOS data area 0:&H417
--           (keyboard flags), 0:&H449 (video mode), 0:&H46C (the timer's ticks since midnight)
-- Anything else a program reaches (another port, a segment of no emulated memory) is an error
-- naming it, so nothing is silently wrong.
--
-- rt: the runtime's link (draw, to_int, IFC, get_mode, f32) and, from the screen module,
-- take_key() (the next key of the input or nil) and clock() (the virtual clock in seconds).
local M = {}

M.names = { "out_port", "inp", "wait_port", "def_seg", "peek", "poke", "dac_reset", "bsave",
  "bload" }

-- The 64 colours of the EGA palette registers as 6-bit DAC levels: bits 0-2 blue, green, red
-- at 2/3, bits 3-5 at 1/3 (the DAC of the 16-colour modes is loaded with them)
local function ega64(c)
  local function level(hi, lo) return ((c >> hi) & 1) * 42 + ((c >> lo) & 1) * 21 end
  return { level(2, 5), level(1, 4), level(0, 3) }
end

-- The default mode-13h DAC (stdlib/draw/canvas.c has the same, for the pictures): 16 EGA
-- colours, 16 greys, 3 intensities x 3 saturations of a 24-step hue wheel, 8 blacks
local EGA16 = { [0] = 0, 1, 2, 3, 4, 5, 20, 7, 56, 57, 58, 59, 60, 61, 62, 63 }
local function vga256()
  local dac = {}
  for i = 0, 15 do dac[i] = ega64(EGA16[i]) end
  local greys = { 0, 5, 8, 11, 14, 17, 20, 24, 28, 32, 36, 40, 45, 50, 56, 63 }
  for i = 0, 15 do dac[16 + i] = { greys[i + 1], greys[i + 1], greys[i + 1] } end
  local levels = {
    { { 0, 16, 31, 47, 63 }, { 31, 39, 47, 55, 63 }, { 45, 49, 54, 58, 63 } },
    { { 0, 7, 14, 21, 28 }, { 14, 17, 21, 24, 28 }, { 20, 22, 24, 26, 28 } },
    { { 0, 4, 8, 12, 16 }, { 8, 10, 12, 14, 16 }, { 11, 12, 13, 15, 16 } } }
  local k = 32
  for int = 1, 3 do
    for sat = 1, 3 do
      local l = levels[int][sat]
      local function L(i) return l[i + 1] end
      for h = 0, 23 do
        local r, g, b
        if h < 4 then r, g, b = L(h), L(0), L(4)
        elseif h < 8 then r, g, b = L(4), L(0), L(8 - h)
        elseif h < 12 then r, g, b = L(4), L(h - 8), L(0)
        elseif h < 16 then r, g, b = L(16 - h), L(4), L(0)
        elseif h < 20 then r, g, b = L(0), L(4), L(h - 16)
        else r, g, b = L(0), L(24 - h), L(4) end
        dac[k] = { r, g, b }
        k = k + 1
      end
    end
  end
  while k < 256 do dac[k] = { 0, 0, 0 }; k = k + 1 end
  return dac
end

-- which attributes of a mode show DAC entry i: the palette registers the BIOS sets
local ATTR_REGS = {
  [7] = { [0] = 0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23 },
  [9] = EGA16, [11] = { [0] = 0, 63 }, [12] = EGA16 }

-- scan codes of the keys an input can give (the US layout's make codes)
local SCAN = {}
do
  local rows = { { "1234567890-=", 2 }, { "qwertyuiop[]", 16 }, { "asdfghjkl;'`", 30 },
    { "\\zxcvbnm,./", 43 } }
  for _, r in ipairs(rows) do
    for i = 1, #r[1] do
      local c = r[1]:sub(i, i)
      SCAN[c] = r[2] + i - 1
      SCAN[c:upper()] = r[2] + i - 1
    end
  end
  for c, code in pairs({ ["!"] = 2, ["@"] = 3, ["#"] = 4, ["$"] = 5, ["%"] = 6, ["^"] = 7,
      ["&"] = 8, ["*"] = 9, ["("] = 10, [")"] = 11, ["_"] = 12, ["+"] = 13, ["{"] = 26,
      ["}"] = 27, [":"] = 39, ['"'] = 40, ["~"] = 41, ["|"] = 43, ["<"] = 51, [">"] = 52,
      ["?"] = 53, [" "] = 57, ["\27"] = 1, ["\r"] = 28, ["\t"] = 15, ["\8"] = 14 }) do
    SCAN[c] = code
  end
end
-- an extended key (CHR$(0) + code): its scan code is the code's byte (H up, P down, ...)
local function scan_code(key)
  if #key == 2 and key:byte(1) == 0 then return key:byte(2) end
  return SCAN[key] or 0
end

-- the BIOS's video mode number of each SCREEN mode (the byte at 0:&H449)
local BIOS_MODE = { [0] = 3, [1] = 4, [2] = 6, [7] = 0xD, [8] = 0xE, [9] = 0x10, [11] = 0x11,
  [12] = 0x12, [13] = 0x13 }

-- the address of a PEEK or POKE as text, for the messages
local function where(seg, off)
  return string.format("&H%X:&H%X", seg, off)
end

local function install_ports(E, rt, H)
  local IFC, to_int = rt.IFC, rt.to_int
  local h_palette = rt.draw("palette")
  -- a DAC entry changed: the attributes that show it take the colour
  local function show(i)
    local m = rt.get_mode()
    local rgb = H.dac[i]
    local c = rgb[3] * 65536 + rgb[2] * 256 + rgb[1]
    if m == 13 then h_palette(i, c) return end
    local regs = ATTR_REGS[m]
    if not regs then return end
    for attr = 0, 15 do if regs[attr] == i then h_palette(attr, c) end end
  end
  H.show = show
  local function byte(v, level) return to_int(v, -32768, 65535, level + 1) & 255 end

  function E.out_port(port, v)
    port = to_int(port, -32768, 65535, 2) & 0xFFFF
    v = to_int(v, -32768, 32767, 2)
    if v < 0 or v > 255 then error(IFC, 2) end
    if port == 0x3C8 then H.write_index, H.write_comp = v, 1
    elseif port == 0x3C7 then H.read_index, H.read_comp = v, 1
    elseif port == 0x3C9 then
      local e = H.dac[H.write_index]
      e[H.write_comp] = v & 63
      H.write_comp = H.write_comp + 1
      if H.write_comp > 3 then
        show(H.write_index)
        H.write_index, H.write_comp = (H.write_index + 1) & 255, 1
      end
    elseif port == 0x3C6 then   -- the DAC's pixel mask: all bits on, as the BIOS leaves it
      if v ~= 255 then error(string.format("OUT &H3C6 (the DAC pixel mask) with &H%X: not supported by pointcalc", v), 2) end
    else
      error(string.format("OUT to port &H%X: not supported by pointcalc (the VGA DAC ports &H3C7, &H3C8, &H3C9 are)", port), 2)
    end
  end
  function E.inp(port)
    port = to_int(port, -32768, 65535, 2) & 0xFFFF
    if port == 0x3C9 then
      local v = H.dac[H.read_index][H.read_comp]
      H.read_comp = H.read_comp + 1
      if H.read_comp > 3 then H.read_index, H.read_comp = (H.read_index + 1) & 255, 1 end
      return v
    elseif port == 0x3C8 then return H.write_index
    elseif port == 0x3C6 then return 255
    elseif port == 0x3DA then
      -- the retrace bit (8) flips at every read, each read a step of the virtual clock
      H.retrace = not H.retrace
      rt.advance(1 / 140)
      return H.retrace and 9 or 0
    elseif port == 0x60 then
      local k = rt.take_key()
      if k then H.scan = scan_code(k) return H.scan end
      rt.empty_poll()
      return H.scan | 0x80            -- no new key: the last one, released
    end
    error(string.format("INP from port &H%X: not supported by pointcalc (&H3C7-&H3C9, &H3DA and &H60 are)", port), 2)
  end
  -- WAIT port, and [, xor]: until (INP(port) XOR xor) AND and is not 0; only the retrace
  -- register is emulated, where each wait is a tick of the virtual clock
  function E.wait_port(port, a, x)
    port = to_int(port, -32768, 65535, 2) & 0xFFFF
    a, x = byte(a, 2), x and byte(x, 2) or 0
    if port ~= 0x3DA then
      error(string.format("WAIT on port &H%X: not supported by pointcalc (WAIT &H3DA, the retrace, is)", port), 2)
    end
    if a == 0 then error(IFC, 2) end
    rt.advance(1 / 70)
    H.retrace = ((8 ~ x) & a) ~= 0
  end
end

local function install_memory(E, rt, H)
  local IFC, to_int = rt.IFC, rt.to_int
  local h_pset, h_point = rt.draw("pset"), rt.draw("point")
  function E.def_seg(seg)
    if seg == nil then H.seg = nil return end
    seg = to_int(seg, -2147483648, 2147483647, 2)
    if seg < -32768 or seg > 65535 then error(IFC, 2) end
    H.seg = seg & 0xFFFF
  end
  -- the byte at DEF SEG's segment and offset: the emulated memory's, else an error naming it
  local function locate(off, level)
    off = to_int(off, -2147483648, 2147483647, level + 1)
    if off < -32768 or off > 65535 then error(IFC, level + 1) end
    off = off & 0xFFFF
    local seg = H.seg
    if seg == nil then
      error("PEEK/POKE without DEF SEG (QBasic's own data segment): not supported by pointcalc", level + 1)
    end
    return seg, off, seg * 16 + off
  end
  local function video(seg, off, level)
    if rt.get_mode() ~= 13 then
      error("video memory " .. where(seg, off) .. " outside SCREEN 13: not supported by pointcalc", level + 1)
    end
    if rt.window_or_view() then
      error("video memory " .. where(seg, off) .. " with WINDOW or VIEW in force: not supported by pointcalc", level + 1)
    end
    local a = seg * 16 + off - 0xA0000
    if a >= 64000 then return nil end       -- past the last pixel: memory nobody shows
    return a % 320, a // 320
  end
  function E.peek(off)
    local seg, o, a = locate(off, 2)
    if a >= 0xA0000 and a < 0xB0000 then
      local x, y = video(seg, o, 2)
      if not x then return H.spare[a] or 0 end
      return h_point(x, y)
    elseif a == 0x417 then return H.kbflags
    elseif a == 0x418 then return 0
    elseif a == 0x449 then return BIOS_MODE[rt.get_mode()] or 3
    elseif a >= 0x46C and a <= 0x46F then
      local ticks = math.floor(rt.clock() * 18.2065) % 0x1800B0
      return (ticks >> (8 * (a - 0x46C))) & 255
    end
    error("PEEK at " .. where(seg, o) .. ": not supported by pointcalc (emulated: &HA000 in SCREEN 13, 0:&H417, 0:&H449, 0:&H46C)", 2)
  end
  function E.poke(off, v)
    local seg, o, a = locate(off, 2)
    v = to_int(v, -32768, 32767, 2)
    if v < 0 or v > 255 then error(IFC, 2) end
    if a >= 0xA0000 and a < 0xB0000 then
      local x, y = video(seg, o, 2)
      if not x then H.spare[a] = v return end
      h_pset(x, y, v)
    elseif a == 0x417 then H.kbflags = v
    else
      error("POKE at " .. where(seg, o) .. ": not supported by pointcalc (emulated: &HA000 in SCREEN 13, 0:&H417)", 2)
    end
  end
end

-- BSAVE and BLOAD: a file of QBasic's format (the byte &HFD, the segment, offset and length as
-- 16-bit little-endian numbers, then the bytes) of the emulated memory: SCREEN 13's pixels
local function install_bsave(E, rt, H)
  local to_int = rt.to_int
  local files = require("qbasic_files")
  local function path_of(name, level)
    return files.resolve(files.folder_of(rt.chunkname), name, level + 1)
  end
  function E.bsave(name, off, len)
    off = to_int(off, -32768, 65535, 2) & 0xFFFF
    len = to_int(len, -32768, 65535, 2) & 0xFFFF
    local seg = H.seg or 0
    local t = {}
    for i = 0, len - 1 do t[#t + 1] = string.char(E.peek(off + i)) end
    local p = files.existing(path_of(name, 2)) or path_of(name, 2)
    local ok, h = pcall(io.open, p, "wb")
    if not ok then error("Permission denied (" .. tostring(h) .. ")", 2) end
    if not h then error("Path not found", 2) end
    h:write(string.pack("<BI2I2I2", 0xFD, seg, off, len))
    h:write(table.concat(t))
    h:close()
  end
  function E.bload(name, off)
    local p = files.existing(path_of(name, 2))
    if not p then error("File not found", 2) end
    local ok, h = pcall(io.open, p, "rb")
    if not ok then error("Permission denied (" .. tostring(h) .. ")", 2) end
    local s = h:read("a")
    h:close()
    if #s < 7 or s:byte(1) ~= 0xFD then error("Bad file mode (not a BSAVE file)", 2) end
    local _, fseg, foff, flen = string.unpack("<BI2I2I2", s)
    if off == nil then   -- the segment and offset the file was saved from
      H.seg, off = fseg, foff
    else
      off = to_int(off, -32768, 65535, 2) & 0xFFFF
    end
    local data = s:sub(8, 7 + flen)
    for i = 1, #data do E.poke(off + i - 1, data:byte(i)) end
  end
end

function M.install(E, rt)
  local H = { write_index = 0, write_comp = 1, read_index = 0, read_comp = 1, retrace = false,
    scan = 0, kbflags = 0, seg = nil, spare = {} }
  -- SCREEN: the DAC the BIOS loads for the new mode
  function rt.dac_reset(m)
    if m == 13 then H.dac = vga256()
    else
      H.dac = {}
      for i = 0, 255 do H.dac[i] = i < 64 and ega64(i) or { 0, 0, 0 } end
    end
  end
  -- PALETTE attr, c in SCREEN 12 and 13 writes the DAC entry the attribute shows
  function rt.dac_set(m, attr, c)
    local i = m == 13 and attr or (ATTR_REGS[m] or EGA16)[attr]
    if c == nil then rt.dac_reset(m) return end
    H.dac[i] = { c & 63, (c >> 8) & 63, (c >> 16) & 63 }
  end
  rt.dac_reset(12)
  install_ports(E, rt, H)
  install_memory(E, rt, H)
  install_bsave(E, rt, H)
end

return M
