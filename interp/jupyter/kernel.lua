-- The pointcalc side of the Jupyter kernel (pointcalc_kernel.py starts `pointcalc kernel.lua`
-- once per notebook): one Lua state whose globals live on from cell to cell.
--
-- Requests come on the file descriptor PC_KERNEL_REQUESTS and replies go to PC_KERNEL_REPLIES
-- (pipes the kernel opened), so that the cell's own
-- output (print, io.write, the C side's messages) stays on standard output and error, which
-- the kernel forwards as streams. A request is a line "VERB NBYTES ARG\n" and NBYTES of text;
-- a reply is any number of frames "TAG NBYTES\n" + NBYTES, the last one "done".
--   exec N FLAGS      run a cell; FLAGS: svg, png or print (the figure's look)
--   complete N POS    completion of the cell text at byte POS
--   inspect N POS     the registry's signature and description of the name at POS
-- Interrupts: the kernel creates the file named by PC_KERNEL_STOP; a count hook looks for it
-- every million VM instructions and stops the cell with "interrupted".
local repl = require "repl"
local help = require "help"

local req = assert(io.open("/dev/fd/" .. assert(os.getenv("PC_KERNEL_REQUESTS"), "run by pointcalc_kernel.py"), "rb"))
local rep = assert(io.open("/dev/fd/" .. assert(os.getenv("PC_KERNEL_REPLIES")), "wb"))
local stop_file = os.getenv("PC_KERNEL_STOP")
local tmp = os.getenv("PC_KERNEL_TMP") or "/tmp"

local function frame(tag, text)
  text = text or ""
  rep:write(tag, " ", #text, "\n", text)
end

-- the hook that makes an interrupt stop a runaway cell
local function stop_requested()
  local f = stop_file and io.open(stop_file, "r")
  if f then f:close(); os.remove(stop_file); return true end
  return false
end
local function hook()
  if stop_requested() then error("interrupted", 2) end
end

-- A cell: an expression shows its values, anything else runs as a chunk named "cell" so that
-- errors read "cell:LINE: message". Lines starting with ":" are REPL commands (:help only).
local function run_cell(code)
  if code:match("^%s*:") then
    local ok, err = pcall(function()
      for line in code:gmatch("[^\n]+") do
        if line:match("^%s*:") then
          local word = line:match("^%s*:(%a*)")
          if word ~= "" and ("help"):sub(1, #word) == word then repl.command(line)
          else error(":" .. word .. " is a REPL command; in a notebook only :help applies", 0) end
        end
      end
    end)
    return ok, err
  end
  local chunk, err = load("return " .. code, "=cell", "t")
  local expression = chunk ~= nil
  if not chunk then chunk, err = load(code, "=cell", "t") end
  if not chunk then return false, err end
  debug.sethook(hook, "", 1000000)
  local result = table.pack(xpcall(chunk, repl.on_error))
  debug.sethook()
  if not result[1] then
    -- the traceback ends at the cell: this driver's own frames are not the user's
    local lines = {}
    for line in tostring(result[2]):gmatch("[^\n]+") do
      if not (line:find("kernel.lua:", 1, true) or line:match("^%s*%[C%]: in function 'xpcall'")
              or line:match("^%s*%(%.%.%.tail calls%.%.%.%)")) then
        lines[#lines + 1] = line
      end
    end
    if lines[#lines] == "stack traceback:" then lines[#lines] = nil end
    return false, table.concat(lines, "\n")
  end
  if expression then
    local text = repl.results(table.unpack(result, 2, result.n))
    if text then frame("result", text) end
  end
  return true
end

-- the canvas as SVG (the way to tell whether a cell drew: it changed, or it called a drawing
-- function), and in the format asked for
local last_svg
local function read_all(path)
  local f = io.open(path, "rb")
  if not f then return nil end
  local s = f:read("a")
  f:close()
  os.remove(path)
  return s
end

local DRAWS = {"pset", "preset", "line", "line_to", "circle", "paint", "path", "fill", "label",
               "text", "screen", "cls", "draw", "wireframe", "shade", "grid", "print_at", "put_block",
               "save", "figure", "axes", "arrow", "dimension"}
local function calls_drawing(code)
  for _, name in ipairs(DRAWS) do
    if code:find("%f[%w_]" .. name .. "%s*[%(%{\"']") then return true end
  end
  return false
end

local function figure(code, flags)
  local path = tmp .. "/cell.svg"
  local ok = pcall(save, path)
  local svg = ok and read_all(path)
  if not svg then return end
  local changed = svg ~= last_svg
  last_svg = svg
  if not (changed or calls_drawing(code)) then return end
  if flags == "png" then
    if pcall(save, tmp .. "/cell.png") then frame("image/png", read_all(tmp .. "/cell.png")) end
  elseif flags == "print" then
    local pok, perr = pcall(save, tmp .. "/cell.pdf")
    if pok then
      frame("application/pdf", read_all(tmp .. "/cell.pdf"))
    else
      frame("stderr", "the print look needs a pointcalc that writes PDF (" ..
            tostring(perr):gsub("^.-: ", "") .. "); showing the SVG\n")
    end
    frame("image/svg+xml", svg)
  else
    frame("image/svg+xml", svg)
  end
end

-- the word before byte pos: a name with its dots and colons (map.sc, c:spl)
local function word_at(code, pos)
  local before = code:sub(1, pos)
  local word = before:match("[%a_][%w_.:]*$") or ""
  return word, before:sub(1, #before - #word)
end

local function complete(code, pos)
  local word, before = word_at(code, pos)
  local found = repl.complete(word, before:match("[^\n]*$"))
  if type(found) ~= "table" then found = {} end
  frame("start", tostring(pos - #word))
  frame("matches", table.concat(found, "\n"))
end

local function inspect(code, pos)
  local word = word_at(code, pos)
  -- the name under the cursor: extend to the right too ("ler|p(" -> lerp)
  word = word .. (code:sub(pos + 1):match("^[%w_]*") or "")
  local e = help.find(word) or help.find((word:gsub("^.*[.:]", "")))
  if e then
    frame("inspect", table.concat(help.forms(e), "\n") .. "\n\n" .. e.desc)
  end
end

-- the canvas as it starts, so that a first cell which draws nothing shows nothing
do
  local path = tmp .. "/cell.svg"
  if pcall(save, path) then last_svg = read_all(path) end
end

while true do
  local head = req:read("l")
  if not head then break end
  local verb, n, arg = head:match("^(%a+) (%d+) ?(.*)$")
  local text = n and req:read(tonumber(n)) or ""
  if verb == "exec" then
    local ok, err = run_cell(text)
    io.stdout:flush(); io.stderr:flush()
    if ok then figure(text, arg) else frame("error", tostring(err)) end
  elseif verb == "complete" then
    complete(text, tonumber(arg) or #text)
  elseif verb == "inspect" then
    inspect(text, tonumber(arg) or #text)
  else
    frame("error", "kernel.lua: unknown request " .. head)
  end
  io.stdout:flush(); io.stderr:flush()
  frame("done")
  rep:flush()
end
