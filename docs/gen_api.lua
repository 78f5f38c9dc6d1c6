-- Generate docs/api.md from the help registry (interp/help.lua), the same text :help prints:
--   pointcalc docs/gen_api.lua > docs/api.md
-- tests/cli/test_api_doc.sh fails when docs/api.md and the registry disagree.
local help = require "help"

local out = {}
local function put(...)
  for _, s in ipairs({...}) do out[#out + 1] = s end
end

-- Inside a table cell: code spans keep their text, pipes must be escaped.
local function cell(s)
  return (s:gsub("|", "\\|"))
end

-- Prose: also keep * and _ from turning into emphasis (A*t + B*bar(t), line_to).
local function prose(s)
  return (cell(s):gsub("([*_])", "\\%1"))
end

local function anchor(title)
  return (title:lower():gsub("[^%w%s-]", ""):gsub("%s", "-"))
end

put("# API reference\n\n")
put("<!-- Generated from interp/help.lua by `pointcalc docs/gen_api.lua > docs/api.md`; ",
    "do not edit by hand. -->\n\n")
put("Every public name of pointcalc, by area. In the REPL, `:help NAME` prints the same ",
    "signature and description, and `:help AREA` a whole area.\n\n")
for _, a in ipairs(help.areas) do
  put("- [", a.title, "](#", anchor(a.title), ")\n")
end
put("\n")
for _, a in ipairs(help.areas) do
  put("## ", a.title, "\n\n", a.intro)
  if a.guide then put(" See [", a.guide, "](", a.guide, ").") end
  put("\n\n| name | signature | description |\n|---|---|---|\n")
  for _, e in ipairs(a.entries) do
    local forms = {}
    for i, f in ipairs(help.forms(e)) do forms[i] = "`" .. cell(f) .. "`" end
    put("| `", cell(e.name), "` | ", table.concat(forms, "<br>"), " | ", prose(e.desc), " |\n")
  end
  put("\n")
end
io.write((table.concat(out):gsub("\n+$", "\n")))
