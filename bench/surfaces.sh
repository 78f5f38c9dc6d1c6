#!/bin/sh
# Benchmark: the 40 x 40 surface z = 0.5 sin 3x cos 2y on [-1, 1]^2 seen orthographically from
# the direction (4, 2, 3), drawn as a wireframe of 40 + 40 iso-lines with the hidden parts
# dashed (the depth test of stdlib/geom/hidden.c), written to PNG and SVG: each whole process
# timed (best of 3), against the same wireframe without hidden-line removal computed in plain
# Lua (numbers, its own projection, line() segments) in the same run; then the same surface
# shaded (s:shade: 40 x 40 quads with Lambert shades, painter's order, the mesh) against the
# same shading computed in plain Lua numbers and drawn with fill() and path().
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
cat > "$tmp/shade.lua" <<'LUA'
-- the same surface shaded: 40 x 40 quads, Lambert shades of white, painter's order, black mesh
local w = unit(V(4, 2, 3))
local r = unit(cross(V(0, 0, 1), w))
local u = cross(w, r)
local view = map.matrix({{r.x, r.y, r.z, 0}, {u.x, u.y, u.z, 0}, {0, 0, 0, 1}})
camera(map.translate(V(320, 250)) * map.scale({150, -150}) * view)
local s = surface(function(x, y) return P(x, y, 0.5 * math.sin(3 * x) * math.cos(2 * y)) end, -1, 1, -1, 1)
s:shade{nu = 40, nv = 40, color = "#ffffff", mesh = "#000000", light = V(1, -1, 3)}
LUA
cat > "$tmp/plain_shade.lua" <<'LUA'
-- the same shaded surface in plain Lua: grid, diagonal normals, cosines, depth sort, then
-- fill and path per quad
local wx, wy, wz = 4, 2, 3
local n = math.sqrt(wx * wx + wy * wy + wz * wz); wx, wy, wz = wx / n, wy / n, wz / n
local rx, ry, rz = -wy, wx, 0
n = math.sqrt(rx * rx + ry * ry); rx, ry = rx / n, ry / n
local ux, uy, uz = wy * rz - wz * ry, wz * rx - wx * rz, wx * ry - wy * rx
local lx, ly, lz = 1, -1, 3
n = math.sqrt(lx * lx + ly * ly + lz * lz); lx, ly, lz = lx / n, ly / n, lz / n
local function f(x, y) return 0.5 * math.sin(3 * x) * math.cos(2 * y) end
local N, X, Y, Z = 40, {}, {}, {}
for i = 0, N do
  X[i], Y[i], Z[i] = {}, {}, {}
  for j = 0, N do
    local x, y = -1 + 2 * i / N, -1 + 2 * j / N
    X[i][j], Y[i][j], Z[i][j] = x, y, f(x, y)
  end
end
local quads = {}
for i = 0, N - 1 do
  for j = 0, N - 1 do
    local ax, ay, az = X[i + 1][j + 1] - X[i][j], Y[i + 1][j + 1] - Y[i][j], Z[i + 1][j + 1] - Z[i][j]
    local bx, by, bz = X[i][j + 1] - X[i + 1][j], Y[i][j + 1] - Y[i + 1][j], Z[i][j + 1] - Z[i + 1][j]
    local nx, ny, nz = ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx
    local len = math.sqrt(nx * nx + ny * ny + nz * nz)
    if nx * wx + ny * wy + nz * wz < 0 then len = -len end
    local c = math.max(0, (nx * lx + ny * ly + nz * lz) / len)
    local cx = (X[i][j] + X[i + 1][j] + X[i + 1][j + 1] + X[i][j + 1]) / 4
    local cy = (Y[i][j] + Y[i + 1][j] + Y[i + 1][j + 1] + Y[i][j + 1]) / 4
    local cz = (Z[i][j] + Z[i + 1][j] + Z[i + 1][j + 1] + Z[i][j + 1]) / 4
    quads[#quads + 1] = {i = i, j = j, c = c, d = cx * wx + cy * wy + cz * wz}
  end
end
table.sort(quads, function(a, b) return a.d < b.d end)
local function px(i, j)
  local x, y, z = X[i][j], Y[i][j], Z[i][j]
  return P(320 + 150 * (rx * x + ry * y + rz * z), 250 - 150 * (ux * x + uy * y + uz * z))
end
for _, q in ipairs(quads) do
  local i, j = q.i, q.j
  local k = math.floor(255 * q.c + 0.5)
  local pts = {px(i, j), px(i + 1, j), px(i + 1, j + 1), px(i, j + 1)}
  fill(pts, string.format("#%02x%02x%02x", k, k, k), "nonzero")
  path(pts, {closed = true, color = "#000000"})
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
c=$(best shade.lua)
d=$(best plain_shade.lua)
echo "surface 40 x 40, hidden lines dashed, PNG + SVG, whole process: $a ms"
echo "the same wireframe in plain Lua without hidden lines:         $b ms"
echo "surface 40 x 40 shaded with its mesh (s:shade), PNG + SVG:      $c ms"
echo "the same shading in plain Lua (fill and path per quad):         $d ms"
