#!/bin/sh
# Benchmark: the 40 x 40 surface z = 0.5 sin 3x cos 2y on [-1, 1]^2 seen orthographically from
# the direction (4, 2, 3), drawn as a wireframe of 40 + 40 iso-lines with the hidden parts
# dashed (the depth test of stdlib/geom/hidden.c), written to PNG and SVG: each whole process
# timed (best of 3), against the same wireframe without hidden-line removal computed in plain
# Lua (numbers, its own projection, line() segments) in the same run.
#   sh bench/surfaces.sh POINTCALC.  A benchmark, not a test.
pc=${1:-build/pointcalc}
case "$pc" in /*) ;; *) pc="$(pwd)/$pc" ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/pc.lua" <<'LUA'
-- the picture plane: x to the right and y up as seen from (4, 2, 3), z up in space
local w = unit(V(4, 2, 3))
local r = unit(cross(V(0, 0, 1), w))
local u = cross(w, r)
local view = map.matrix({{r.x, r.y, r.z, 0}, {u.x, u.y, u.z, 0}, {0, 0, 0, 1}})
camera(map.translate(V(320, 250)) * map.scale({150, -150}) * view)
local s = surface(function(x, y) return P(x, y, 0.5 * math.sin(3 * x) * math.cos(2 * y)) end, -1, 1, -1, 1)
s:wireframe{nu = 40, nv = 40, color = 15, hidden = "dashed"}
LUA
cat > "$tmp/plain.lua" <<'LUA'
-- the same wireframe in plain Lua: no hidden lines
local wx, wy, wz = 4, 2, 3
local n = math.sqrt(wx * wx + wy * wy + wz * wz); wx, wy, wz = wx / n, wy / n, wz / n
local rx, ry, rz = -wy, wx, 0                               -- z x w
n = math.sqrt(rx * rx + ry * ry); rx, ry = rx / n, ry / n
local ux, uy, uz = wy * rz - wz * ry, wz * rx - wx * rz, wx * ry - wy * rx
local function f(x, y) return 0.5 * math.sin(3 * x) * math.cos(2 * y) end
local function px(x, y, z) return 320 + 150 * (rx * x + ry * y + rz * z), 250 - 150 * (ux * x + uy * y + uz * z) end
local steps = 200                                           -- points per iso-line
for i = 0, 40 do
  local a = -1 + 2 * i / 40
  local x0, y0 = px(a, -1, f(a, -1))
  local x1, y1 = px(-1, a, f(-1, a))
  for j = 1, steps do
    local b = -1 + 2 * j / steps
    local x, y = px(a, b, f(a, b)); line(x0, y0, x, y, 15); x0, y0 = x, y
    x, y = px(b, a, f(b, a)); line(x1, y1, x, y, 15); x1, y1 = x, y
  end
end
LUA
best() {
    b=""
    for _ in 1 2 3; do
        t0=$(date +%s%N)
        (cd "$tmp" && "$pc" "$1" -o out.png -o out.svg > /dev/null) || exit 1
        t=$(( ($(date +%s%N) - t0) / 1000000 ))
        [ -z "$b" ] || [ "$t" -lt "$b" ] && b=$t
    done
    echo "$b"
}
a=$(best pc.lua)
b=$(best plain.lua)
echo "surface 40 x 40, hidden lines dashed, PNG + SVG, whole process: $a ms"
echo "the same wireframe in plain Lua without hidden lines:         $b ms"
