-- A tiny assertion library for the Lua-level tests: each check names what it checks, a
-- failure raises an error at the caller's line (exit status 1).
--   local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local check = { count = 0 }

local function show(v)
  if type(v) == "string" then return string.format("%q", v) end
  return tostring(v)
end

function check.eq(got, want, what)
  check.count = check.count + 1
  if got ~= want then
    error(string.format("%s: got %s, want %s", what or "eq", show(got), show(want)), 2)
  end
end

function check.near(got, want, tol, what)
  check.count = check.count + 1
  if type(got) ~= "number" or math.abs(got - want) > tol then
    error(string.format("%s: got %s, want %s +- %g", what or "near", show(got), show(want), tol), 2)
  end
end

-- check.err(fn, text, what): fn must fail, with `text` (plain) in the message
function check.err(fn, text, what)
  check.count = check.count + 1
  local ok, msg = pcall(fn)
  if ok then error((what or "err") .. ": no error, want one containing " .. show(text), 2) end
  if not tostring(msg):find(text, 1, true) then
    error(string.format("%s: message %s does not contain %s", what or "err", show(msg), show(text)), 2)
  end
end

-- check.same_within(tol) gives same(p, q, what [, tol]): two points or vectors equal within
-- tol (pointcalc's near), tol defaulting to the given one
local pc_near = near or require("pointcalc").near
function check.same_within(default_tol)
  return function(p, q, what, tol)
    check.count = check.count + 1
    if not pc_near(p, q, tol or default_tol) then
      error(string.format("%s: got %s, want %s", what or "same", tostring(p), tostring(q)), 2)
    end
  end
end

function check.truthy(v, what)
  check.count = check.count + 1
  if not v then error((what or "truthy") .. ": got " .. show(v), 2) end
end

function check.done()
  -- a test draws to check pixels, not to make a picture: leave no default output behind
  if save then
    local tmp = os.tmpname()
    save(tmp .. ".ppm")
    os.remove(tmp .. ".ppm")
    os.remove(tmp)
  end
  print(string.format("%s: %d checks passed", arg and arg[0] or "test", check.count))
end

return check
