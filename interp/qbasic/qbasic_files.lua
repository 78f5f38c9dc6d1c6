-- QBasic front end, runtime part 4: files.  OPEN (sequential INPUT, OUTPUT, APPEND; RANDOM
-- records; BINARY), CLOSE, PRINT #, WRITE #, INPUT #, LINE INPUT #, GET #, PUT #, FIELD,
-- EOF, LOF, LOC, SEEK, FREEFILE, KILL, NAME, with QBasic's errors (File not found, Bad file
-- mode, Input past end of file, ...).
--
-- A program reaches only files in its own folder and below: a name is relative, with no ".."
-- (DOS's backslashes are folders); in the safe mode the host's io functions also check the
-- --allow folders.  Lines end in CR LF as DOS writes them; reading accepts LF alone and stops at
-- Ctrl-Z.
--
-- install(E, rt, fmt): rt has to_int, IFC, chunkname; fmt(v, kind) is PRINT's number text.
local M = {}

M.names = { "open_file", "close_files", "fprint", "write_items", "finput", "flineinput",
  "get_record", "put_record", "field", "seek_file", "kill_file", "name_file", "eof_", "lof_",
  "loc_", "freefile", "seek_" }

-- the folder of the program (its chunk name as given on the command line)
local function folder_of(chunkname)
  return chunkname:match("^(.*)/[^/]*$") or "."
end

-- a file name of the program: relative, under its folder
local function resolve(dir, name, level)
  local n = name:gsub("\\", "/")
  if n == "" then error("Bad file name", level + 1) end
  if n:match("^/") or n:match("^%a:") then
    error("Path/File access error (" .. name .. ": a QBasic program reaches files in its folder "
      .. "and below only)", level + 1)
  end
  for part in n:gmatch("[^/]+") do
    if part == ".." then
      error("Path/File access error (" .. name .. ": a QBasic program reaches files in its "
        .. "folder and below only)", level + 1)
    end
  end
  return dir .. "/" .. n
end

-- io.open through the host's checks (the safe mode's): a refusal is QBasic's Permission denied
local function open(path, mode, level)
  local ok, h = pcall(io.open, path, mode)
  if not ok then error("Permission denied (" .. tostring(h):gsub("^[^:]*:%d+: ", "") .. ")", level + 1) end
  return h
end
-- DOS file names are not case-sensitive: an existing file under another case is the same file
-- (a name the safe mode refuses is none: open then says Permission denied)
local function existing(path)
  local dir, base = path:match("^(.*/)([^/]*)$")
  for _, p in ipairs({ path, dir .. base:lower(), dir .. base:upper() }) do
    local ok, h = pcall(io.open, p, "rb")
    if ok and h then h:close() return p end
  end
end

local function install_sequential(E, rt, F)
  local to_int = rt.to_int
  local function file(n, level, modes)
    n = to_int(n, -32768, 32767, level + 1)
    local f = F.open[n]
    if not f then error("Bad file name or number", level + 1) end
    if modes and not modes:find(f.mode, 1, true) then error("Bad file mode", level + 1) end
    return f
  end
  F.file = file
  function E.open_file(name, mode, n, len)
    local m = mode:sub(1, 1):upper()
    if not ("IOARB"):find(m, 1, true) or m == "" then error("Bad file mode", 2) end
    n = to_int(n, -32768, 32767, 2)
    if n < 1 or n > 255 then error("Bad file name or number", 2) end
    if F.open[n] then error("File already open", 2) end
    local path = resolve(F.dir, name, 2)
    local f = { mode = m, path = path, col = 0, reclen = len and to_int(len, -32768, 32767, 2) or 128 }
    if f.reclen < 1 then error("Bad record length", 2) end
    if m == "I" then
      local p = existing(path)
      if not p then error("File not found", 2) end
      local h = open(p, "rb", 2)
      f.data, f.pos = h:read("a"), 1
      h:close()
      local z = f.data:find("\26", 1, true)     -- Ctrl-Z ends a DOS text file
      if z then f.data = f.data:sub(1, z - 1) end
    elseif m == "O" or m == "A" then
      f.h = open(existing(path) or path, m == "O" and "wb" or "ab", 2)
      if not f.h then error("Path not found", 2) end
    else
      local p = existing(path)
      f.h = p and open(p, "r+b", 2) or open(path, "w+b", 2)
      if not f.h then error("Path not found", 2) end
      f.pos = 1
    end
    F.open[n] = f
  end
  function E.close_files(...)
    local t = { ... }
    if #t == 0 then for k in pairs(F.open) do t[#t + 1] = k end end
    for _, n in ipairs(t) do
      local f = file(n, 2)
      if f.h then f.h:close() end
      F.open[to_int(n, -32768, 32767, 2)] = nil
    end
  end
  -- text into a file opened for OUTPUT or APPEND, its column kept for PRINT's zones and TAB
  function F.put(n, s, level)
    local f = file(n, level + 1, "OA")
    s = s:gsub("\n", "\r\n")
    f.h:write(s)
    local nl = s:find("\n[^\n]*$")
    f.col = nl and (#s - nl) or (f.col + #s)
    return f.col
  end
  function F.col(n) return file(n, 3).col end
  function E.write_items(n, ...)
    local t = {}
    for i = 1, select("#", ...) do
      local v = select(i, ...)
      if type(v) == "string" then t[i] = '"' .. v .. '"'
      else t[i] = (rt.number_text(v)) end
    end
    local s = table.concat(t, ",") .. "\n"
    if n == nil then rt.qwrite(s) else F.put(n, s, 2) end
  end
  local function past_end(f, level)
    if f.pos > #f.data then error("Input past end of file", level + 1) end
  end
  -- INPUT #: each field up to a comma or the line's end ("quoted" strings keep their commas);
  -- a number ends at a space too
  function E.finput(n, kinds)
    local f = file(n, 2, "I")
    local r = {}
    for i, k in ipairs(kinds) do
      local d = f.data
      f.pos = d:find("[^ \t\r\n]", f.pos) or #d + 1
      past_end(f, 2)
      local v
      if d:sub(f.pos, f.pos) == '"' then
        local q = d:find('"', f.pos + 1, true) or #d + 1
        v = d:sub(f.pos + 1, q - 1)
        f.pos = q + 1
      else
        local stop = k == "s" and "[,\r\n]" or "[, \t\r\n]"
        local e = d:find(stop, f.pos) or #d + 1
        v = d:sub(f.pos, e - 1)
        if k == "s" then v = v:gsub("%s+$", "") end
        f.pos = e
      end
      -- past the separator: spaces, then one comma or one line end
      f.pos = d:find("[^ \t]", f.pos) or #d + 1
      local c = d:sub(f.pos, f.pos)
      if c == "," then f.pos = f.pos + 1
      elseif c == "\r" then f.pos = f.pos + (d:sub(f.pos + 1, f.pos + 1) == "\n" and 2 or 1)
      elseif c == "\n" then f.pos = f.pos + 1 end
      if k == "s" then r[i] = v
      else r[i] = tonumber((v:gsub("[dD]", "e"):gsub("[!#%%&]$", ""))) or 0 end
    end
    return r
  end
  function E.flineinput(n)
    local f = file(n, 2, "I")
    past_end(f, 2)
    local d = f.data
    local e = d:find("[\r\n]", f.pos) or #d + 1
    local l = d:sub(f.pos, e - 1)
    f.pos = e + ((d:sub(e, e + 1) == "\r\n") and 2 or 1)
    return { l }
  end
  function E.eof_(n)
    local f = file(n, 2)
    if f.mode == "I" then return f.pos > #f.data and -1 or 0 end
    if f.mode == "R" or f.mode == "B" then return f.past_end and -1 or 0 end
    return -1
  end
  function E.lof_(n)
    local f = file(n, 2)
    if f.data then return #f.data end
    local at = f.h:seek()
    local size = f.h:seek("end")
    f.h:seek("set", at)
    return size
  end
  function E.freefile()
    for n = 1, 255 do if not F.open[n] then return n end end
    error("Too many files", 2)
  end
  function E.kill_file(name)
    if name:find("[*?]") then error("KILL with a wildcard: not supported by pointcalc", 2) end
    local p = existing(resolve(F.dir, name, 2))
    if not p then error("File not found", 2) end
    local ok, r = pcall(os.remove, p)
    if not ok or not r then error("Permission denied", 2) end
  end
  function E.name_file(a, b)
    local p = existing(resolve(F.dir, a, 2))
    if not p then error("File not found", 2) end
    local q = resolve(F.dir, b, 2)
    if existing(q) then error("File already exists", 2) end
    local ok, r = pcall(os.rename, p, q)
    if not ok or not r then error("Permission denied", 2) end
  end
end

-- ---- records: RANDOM (fixed-length records, numbered from 1) and BINARY (bytes from 1) -------
local PACK = { int = "<i2", long = "<i4", single = "<f", double = "<d" }
-- a value's bytes by its layout: a number type, {fix = n}, "str" (its own length) or a record's
-- fields in order {{name, layout}, ...}
local function encode(v, layout)
  if PACK[layout] then return string.pack(PACK[layout], v) end
  if layout == "str" then return v end
  if type(layout) == "table" and layout.fix then
    return (v .. string.rep(" ", layout.fix)):sub(1, layout.fix)
  end
  local t = {}
  for i, f in ipairs(layout) do t[i] = encode(v[f[1]], f[2]) end
  return table.concat(t)
end
local function size_of(layout, v)
  if PACK[layout] then return #string.pack(PACK[layout], 0) end
  if layout == "str" then return #v end
  if layout.fix then return layout.fix end
  local n = 0
  for _, f in ipairs(layout) do n = n + size_of(f[2], v and v[f[1]]) end
  return n
end
local function decode(s, at, layout, old)
  if PACK[layout] then
    local fmt = PACK[layout]
    local b = s:sub(at, at + #string.pack(fmt, 0) - 1)
    if #b < #string.pack(fmt, 0) then b = b .. string.rep("\0", #string.pack(fmt, 0) - #b) end
    return (string.unpack(fmt, b)), at + #b
  end
  if layout == "str" or layout.fix then
    local n = layout == "str" and #old or layout.fix
    local b = s:sub(at, at + n - 1)
    return b .. string.rep(layout == "str" and " " or "\0", n - #b), at + n
  end
  local r = {}
  for _, f in ipairs(layout) do r[f[1]], at = decode(s, at, f[2], old and old[f[1]]) end
  return r, at
end

local function install_records(E, rt, F)
  local to_int = rt.to_int
  -- the byte offset of a GET or PUT: RANDOM's record (default: the next), BINARY's position
  local function place(f, rec, level)
    local r = rec and to_int(rec, -2147483648, 2147483647, level + 1)
    if r and r < 1 then error("Bad record number", level + 1) end
    if f.mode == "R" then
      r = r or f.next or 1
      f.next = r + 1
      return (r - 1) * f.reclen
    end
    r = r or f.pos
    return r - 1
  end
  function E.get_record(n, rec, layout, old)
    local f = F.file(n, 2, "RB")
    local at = place(f, rec, 2)
    local size = layout and size_of(layout, old) or f.reclen
    if f.mode == "R" and size > f.reclen then error("FIELD overflow", 2) end
    f.h:seek("set", at)
    local s = f.h:read(f.mode == "R" and f.reclen or size) or ""
    f.past_end = #s < size
    f.pos = at + size + 1
    if not layout then   -- FIELD: the record into the field variables
      local p = 1
      for _, fd in ipairs(f.fields or {}) do
        local v = s:sub(p, p + fd[1] - 1)
        E[fd[2]] = v .. string.rep(" ", fd[1] - #v)
        p = p + fd[1]
      end
      return nil
    end
    local v = decode(s, 1, layout, old)
    return v
  end
  function E.put_record(n, rec, layout, v)
    local f = F.file(n, 2, "RB")
    local at = place(f, rec, 2)
    local s
    if layout then s = encode(v, layout)
    else
      local t = {}
      for i, fd in ipairs(f.fields or {}) do
        t[i] = ((E[fd[2]] or "") .. string.rep(" ", fd[1])):sub(1, fd[1])
      end
      s = table.concat(t)
    end
    if f.mode == "R" then
      if #s > f.reclen then error("FIELD overflow", 2) end
      s = s .. string.rep("\0", f.reclen - #s)
    end
    f.h:seek("set", at)
    f.h:write(s)
    f.pos = at + #s + 1
  end
  function E.field(n, ...)
    local f = F.file(n, 2, "R")
    local total, fields = 0, {}
    for i, fd in ipairs({ ... }) do
      local w = to_int(fd[1], -32768, 32767, 2)
      if w < 0 then error(rt.IFC, 2) end
      total = total + w
      fields[i] = { w, fd[2] }
      E[fd[2]] = string.rep(" ", w)
    end
    if total > f.reclen then error("FIELD overflow", 2) end
    f.fields = fields
  end
  function E.seek_file(n, pos)
    local f = F.file(n, 2)
    pos = to_int(pos, -2147483648, 2147483647, 2)
    if pos < 1 then error("Bad record number", 2) end
    if f.mode == "R" then f.next = pos
    elseif f.h then f.h:seek("set", pos - 1); f.pos = pos
    else f.pos = pos end
  end
  function E.seek_(n)
    local f = F.file(n, 2)
    if f.mode == "R" then return f.next or 1 end
    if f.h and f.mode ~= "B" then return f.h:seek() + 1 end
    return f.pos
  end
  function E.loc_(n)
    local f = F.file(n, 2)
    if f.mode == "R" then return (f.next or 1) - 1 end
    if f.mode == "I" then return (f.pos - 1) // 128 end
    if f.mode == "B" then return f.pos - 1 end
    return f.h:seek() // 128
  end
end

M.folder_of, M.resolve, M.existing = folder_of, resolve, existing

function M.install(E, rt)
  local F = { open = {}, dir = folder_of(rt.chunkname) }
  install_sequential(E, rt, F)
  install_records(E, rt, F)
  rt.file_put, rt.file_col = F.put, F.col
  -- INPUT$(n, #f): the next n bytes of a file opened for INPUT or BINARY
  function rt.file_chars(k, n)
    local f = F.file(n, 3, "IB")
    k = rt.to_int(k, -32768, 32767, 3)
    if k < 1 then error(rt.IFC, 3) end
    if f.mode == "I" then
      if f.pos + k - 1 > #f.data then error("Input past end of file", 3) end
      local s = f.data:sub(f.pos, f.pos + k - 1)
      f.pos = f.pos + k
      return s
    end
    f.h:seek("set", f.pos - 1)
    local s = f.h:read(k) or ""
    if #s < k then error("Input past end of file", 3) end
    f.pos = f.pos + k
    return s
  end
  rt.close_all = function() for _, f in pairs(F.open) do if f.h then f.h:close() end end end
end

return M
