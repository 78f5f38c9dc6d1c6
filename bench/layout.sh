#!/bin/sh
# Benchmark of the figure layout, whole processes (best of 3), written to PNG and SVG:
#  1. 1,000 automatic labels among 10,000 strokes (short segments at pseudo-random places):
#     placement at write time (stdlib/draw/label_place.c);
#  2. a scene: a 40 x 40 wireframe surface, 100 curves over it and 200 labels, with the
#     hidden parts of every stroke dashed whatever the drawing order (stdlib/draw/scene.c);
# each against Asymptote's nearest figure in the same run, one run each (labels at fixed
# sides, no placement; the 3-D one with settings.render = 0 to PDF, the surface filled white
# for its painter's-order hiding), when asy is installed.   sh bench/layout.sh POINTCALC.  A benchmark, not a test.
pc=${1:-build/pointcalc}
case "$pc" in /*) ;; *) pc="$(pwd)/$pc" ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/labels.lua" <<'LUA'
local seed = 12345
local function rnd() seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648 end
for _ = 1, 10000 do
  local x, y, a = rnd() * 640, rnd() * 480, rnd() * 2 * math.pi
  line(x, y, x + 12 * math.cos(a), y + 12 * math.sin(a), 7)
end
for i = 1, 1000 do label("L" .. i, P(rnd() * 640, rnd() * 480), nil, 14) end
LUA
cat > "$tmp/labels.asy" <<'ASY'
size(640, 480);
int seed = 12345;
real rnd() { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; }
for (int k = 0; k < 10000; ++k) {
  real x = rnd() * 640, y = rnd() * 480, a = rnd() * 2 * pi;
  draw((x, y)--(x + 12 * cos(a), y + 12 * sin(a)), gray);
}
for (int i = 1; i <= 1000; ++i) label("L" + string(i), (rnd() * 640, rnd() * 480), NE);
ASY
cat > "$tmp/scene.lua" <<'LUA'
local view = map.view { azimuth = -60, elevation = 30 }
camera(map.translate(V(320, 250)) * map.scale({ 150, -150 }) * view, { hidden = "dashed" })
local f = function(x, y) return 0.5 * math.sin(3 * x) * math.cos(2 * y) end
for k = 1, 100 do   -- curves over the surface, some of them behind its hills
  local y0 = -1 + 2 * k / 101
  curve(function(t) return P(t, y0, f(t, y0) + 0.05) end, -1, 1):draw { color = 12 }
end
local s = surface(function(x, y) return P(x, y, f(x, y)) end, -1, 1, -1, 1)
s:wireframe { nu = 40, nv = 40, color = 15 }
camera(nil)
for k = 1, 200 do label("c" .. k, P(20 + (k * 37) % 600, 20 + (k * 53) % 440), nil, 14) end
LUA
cat > "$tmp/scene.asy" <<'ASY'
import graph3;
settings.render = 0;
size(640, 480);
currentprojection = orthographic(dir(60, -60));
real f(pair p) { return 0.5 * sin(3 * p.x) * cos(2 * p.y); }
surface s = surface(f, (-1, -1), (1, 1), nx = 40, Spline);
draw(s, white, meshpen = black);   // filled white: its own painter's-order hiding
for (int k = 1; k <= 100; ++k) {
  real y0 = -1 + 2 * k / 101;
  draw(graph(new triple(real t) { return (t, y0, f((t, y0)) + 0.05); }, -1, 1, operator ..), red);
}
for (int k = 1; k <= 200; ++k) label("c" + string(k), ((k * 37) % 600 / 300 - 1, (k * 53) % 440 / 220 - 1, 0.6));
ASY
best() {   # best DIR CMD...: the best of 3 runs in ms
    b=""
    for _ in 1 2 3; do
        t0=$(date +%s%N)
        (cd "$tmp" && "$@" > /dev/null 2>&1) || { echo "failed"; return; }
        t=$(( ($(date +%s%N) - t0) / 1000000 ))
        [ -z "$b" ] || [ "$t" -lt "$b" ] && b=$t
    done
    echo "$b ms"
}
echo "1,000 automatic labels among 10,000 strokes, PNG + SVG:        $(best "$pc" labels.lua -o out.png -o out.svg)"
echo "40 x 40 surface + 100 curves + 200 labels, hidden dashed:       $(best "$pc" scene.lua -o out.png -o out.svg)"
once() {   # once CMD...: one run in ms (Asymptote takes seconds: one run is enough)
    t0=$(date +%s%N)
    (cd "$tmp" && "$@" > /dev/null 2>&1) || { echo "failed"; return; }
    echo "$(( ($(date +%s%N) - t0) / 1000000 )) ms"
}
if command -v asy > /dev/null; then
    echo "Asymptote, 10,000 strokes and 1,000 labels at fixed sides, PDF: $(once asy -f pdf labels.asy)"
    echo "Asymptote, the 40 x 40 surface, 100 curves, 200 labels, PDF:    $(once asy -f pdf scene.asy)"
fi
echo "(load average when done: $(cut -d' ' -f1 /proc/loadavg) on $(nproc) cores)"
