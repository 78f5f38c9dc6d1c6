-- Benchmark of the Stepanov gallery: each example script rendered by pointcalc (run and write a
-- PPM), against a baseline in plain Lua: the same figure computed by the article's own program
-- (the cleaned listing, translated by the QBasic front end) with plain double numbers and the
-- drawing layer of bench/plain_canvas.lua, writing its own PPM.  Each figure is timed as the
-- best of 3 runs (os.clock).  Run: pointcalc bench/gallery.lua  (needs ../shared/listings)
local root = arg[0]:match("^(.-)bench/[^/]*$") or "./"
if root == "" then root = "./" end
local listings = (os.getenv("PC_SHARED_DIR") or root .. "../shared") .. "/listings/stepanov/"
local qbasic = require "qbasic"
local real_rt = require "qbasic_rt"
local tmp = os.tmpname()

local function best_of(n, fn)
  local best = math.huge
  for _ = 1, n do
    local t0 = os.clock()
    fn()
    best = math.min(best, os.clock() - t0)
  end
  return best
end

local function read(path)
  local f = io.open(path, "rb")
  if not f then return nil end
  local s = f:read("a")
  f:close()
  return s
end

-- the example script in a fresh environment on a fresh canvas
local function run_script(path)
  local env = setmetatable({ arg = { [0] = path } }, { __index = _G })
  local chunk = assert(loadfile(path, "t", env))
  return function()
    screen(12)
    chunk()
    save(tmp .. ".ppm")
  end
end

-- the listing in plain Lua: QBasic's runtime with doubles for SINGLE and the plain canvas
local function run_listing_plain(path)
  local lua_text = assert(qbasic.translate(assert(read(path)), path))
  return function()
    local plain = dofile(root .. "bench/plain_canvas.lua")
    package.loaded.qbasic_rt = {
      new = function(host, name)
        local E = real_rt.new(host, name)
        E.csng = function(x) return x end
        for _, f in ipairs { "screen", "cls", "color", "pset", "preset", "line", "line_to",
                             "circle", "paint", "point", "palette" } do
          E[f] = plain[f]
        end
        return E
      end }
    local ok, err = pcall(assert(load(lua_text, "@" .. path)))
    package.loaded.qbasic_rt = real_rt
    if not ok then error(err, 0) end
    plain.save(tmp .. "-plain.ppm")
  end
end

local names = {}
for name in io.popen("ls " .. root .. "examples/stepanov"):lines() do
  if name:match("^%d%d%a?_.*%.lua$") then names[#names + 1] = name end
end
table.sort(names)

print(string.format("%-34s %10s %12s %8s", "example", "pointcalc", "plain Lua", "speed-up"))
local total, total_plain, slower = 0, 0, 0
for _, name in ipairs(names) do
  local num = name:match("^(%d%d%a?)_")
  local t = best_of(3, run_script(root .. "examples/stepanov/" .. name))
  total = total + t
  local listing = listings .. "ex" .. num .. ".bas"
  if not num:match("v$") and read(listing) then
    local tp = best_of(3, run_listing_plain(listing))
    total_plain = total_plain + tp
    if tp <= t then slower = slower + 1 end
    print(string.format("%-34s %8.1f ms %9.1f ms %7.1fx", name, t * 1e3, tp * 1e3, tp / t))
  else
    print(string.format("%-34s %8.1f ms %12s", name, t * 1e3, "(no listing)"))
  end
end
print(string.format("all %d scripts: %.2f s in pointcalc; the listings in plain Lua: %.2f s; examples not faster than plain Lua: %d",
  #names, total, total_plain, slower))
os.remove(tmp); os.remove(tmp .. ".ppm"); os.remove(tmp .. "-plain.ppm")
