-- A drawing layer in plain Lua, for the gallery benchmark's baseline: what a user would write
-- without pointcalc's native canvas.  A 640x480 table of colour numbers with PSET, LINE (and
-- boxes), CIRCLE (with arcs and aspect), PAINT and POINT, and a PPM writer.
local floor, sqrt, atan, pi = math.floor, math.sqrt, math.atan, math.pi
local W, H = 640, 480

local pal = {
  [0] = "\0\0\0", "\0\0\170", "\0\170\0", "\0\170\170", "\170\0\0", "\170\0\170", "\170\85\0",
  "\170\170\170", "\85\85\85", "\85\85\255", "\85\255\85", "\85\255\255", "\255\85\85",
  "\255\85\255", "\255\255\85", "\255\255\255" }

local canvas = {}
local px = {}
local fg = 15

local function plot(x, y, c)
  if x >= 0 and x < W and y >= 0 and y < H then px[y * W + x] = c end
end

function canvas.screen()
  for i = 0, W * H - 1 do px[i] = 0 end
end
canvas.cls = canvas.screen
function canvas.color(c) fg = c end

function canvas.pset(x, y, c)
  plot(floor(x + .5), floor(y + .5), c or fg)
end
function canvas.preset(x, y, c) canvas.pset(x, y, c or 0) end
function canvas.point(x, y)
  x, y = floor(x + .5), floor(y + .5)
  if x < 0 or x >= W or y < 0 or y >= H then return -1 end
  return px[y * W + x]
end

local lastx, lasty = 320, 240
local function segment(x0, y0, x1, y1, c)
  local dx, dy = math.abs(x1 - x0), -math.abs(y1 - y0)
  local sx, sy = x0 < x1 and 1 or -1, y0 < y1 and 1 or -1
  local err = dx + dy
  while true do
    plot(x0, y0, c)
    if x0 == x1 and y0 == y1 then return end
    local e2 = 2 * err
    if e2 >= dy then err = err + dy; x0 = x0 + sx end
    if e2 <= dx then err = err + dx; y0 = y0 + sy end
  end
end

function canvas.line(x1, y1, x2, y2, c, style)
  c = c or fg
  local a, b, d, e = floor(x1 + .5), floor(y1 + .5), floor(x2 + .5), floor(y2 + .5)
  if style == "b" or style == "B" then
    segment(a, b, d, b, c); segment(d, b, d, e, c); segment(d, e, a, e, c); segment(a, e, a, b, c)
  elseif style == "bf" or style == "BF" then
    for y = math.min(b, e), math.max(b, e) do segment(math.min(a, d), y, math.max(a, d), y, c) end
  else
    segment(a, b, d, e, c)
  end
  lastx, lasty = x2, y2
end
function canvas.line_to(x, y, c, style) canvas.line(lastx, lasty, x, y, c, style) end
function canvas.last_point() return lastx, lasty end

function canvas.circle(x, y, r, c, a0, a1, aspect)
  c = c or fg
  local rx, ry = r, r
  if aspect then if aspect < 1 then ry = r * aspect else rx = r / aspect end end
  local cx, cy = floor(x + .5), floor(y + .5)
  rx, ry = floor(rx + .5), floor(ry + .5)
  local full = a0 == nil and a1 == nil
  a0, a1 = math.abs(a0 or 0), math.abs(a1 or 2 * pi)
  local function put(dx, dy)
    if not full then
      local th = atan(-dy, dx); if th < 0 then th = th + 2 * pi end
      if a0 <= a1 then if th < a0 or th > a1 then return end
      elseif th < a0 and th > a1 then return end
    end
    plot(cx + dx, cy + dy, c)
  end
  for i = 0, rx do
    local j = rx > 0 and floor(ry * sqrt(math.max(0, 1 - (i / rx) ^ 2)) + .5) or ry
    put(i, j); put(-i, j); put(i, -j); put(-i, -j)
  end
  for j = 0, ry do
    local i = ry > 0 and floor(rx * sqrt(math.max(0, 1 - (j / ry) ^ 2)) + .5) or rx
    put(i, j); put(-i, j); put(i, -j); put(-i, -j)
  end
end

function canvas.paint(x, y, c, border)
  c = c or fg
  border = border or c
  x, y = floor(x + .5), floor(y + .5)
  if x < 0 or x >= W or y < 0 or y >= H or px[y * W + x] == border then return end
  local seen, stack = {}, { y * W + x }
  while #stack > 0 do
    local i = table.remove(stack)
    if not seen[i] and px[i] ~= border then
      seen[i] = true
      px[i] = c
      local xx, yy = i % W, i // W
      if xx > 0 then stack[#stack + 1] = i - 1 end
      if xx < W - 1 then stack[#stack + 1] = i + 1 end
      if yy > 0 then stack[#stack + 1] = i - W end
      if yy < H - 1 then stack[#stack + 1] = i + W end
    end
  end
end

function canvas.window() error("plain canvas: WINDOW is not part of the baseline") end
function canvas.view() error("plain canvas: VIEW is not part of the baseline") end
function canvas.palette() end

-- write the picture as a binary PPM
function canvas.save(path)
  local rows = {}
  for y = 0, H - 1 do
    local row = {}
    for x = 0, W - 1 do row[x + 1] = pal[px[y * W + x]] end
    rows[y + 1] = table.concat(row)
  end
  local f = assert(io.open(path, "wb"))
  f:write(string.format("P6\n%d %d\n255\n", W, H), table.concat(rows))
  f:close()
end

canvas.screen()
return canvas
