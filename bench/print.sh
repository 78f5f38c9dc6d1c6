#!/bin/sh
# Benchmark of the print look.  Two figures, each as PDF and as a 300-dpi PNG, 12 cm wide,
# whole processes, against the same figures in Asymptote (`asy -f pdf`) in the same run:
#   - the conic through five points A..E with its labels (Konopatsky §2.1.4; Asymptote's
#     geometry module: conic(A, B, C, D, E));
#   - the 40 x 40 shaded surface of examples/buimov/07_shaded_surface.lua (Asymptote's
#     surface(f, ..., nx = 40, Spline) drawn white with a black mesh, render = 0: vector).
# pointcalc: best of 3 wall-clock runs; Asymptote: one run (seconds each).  Then the whole
# gallery in both looks: every example to PNG and SVG (VGA look) and to PNG, SVG and PDF
# (print look), on all cores.  Asymptote comes from Debian (apt-get install asymptote); without
# it the comparison is skipped.  sh bench/print.sh [POINTCALC].  A benchmark, not a test.
pc=${1:-build/pointcalc}
case "$pc" in /*) ;; *) pc="$(pwd)/$pc" ;; esac
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cores=$(nproc 2>/dev/null || echo 2)

cat > "$tmp/conic.lua" <<'LUA'
figure{width = "12cm"}
local A, B, C, D, E = P(1, 0), P(0, 1), P(0, 0), P(0.3, 0.8), P(0.7, 0.6)
window(-0.8, -0.5, 2.0, 1.6)
path({A, B, C, A}, {color = 8})
pen "main"
conic.five_points(A, B, C, D, E, {whole = true}):draw{color = 15}
pen()
for _, p in ipairs{A, B, C, D, E} do circle(p, 0.01, 15) end
label("$A$", A, "s") label("$B$", B, "w") label("$C$", C, "sw") label("$D$", D, "nw") label("$E$", E, "ne")
LUA
cat > "$tmp/conic.asy" <<'ASY'
import geometry;
size(12cm);
point A = (1, 0), B = (0, 1), C = (0, 0), D = (0.3, 0.8), E = (0.7, 0.6);
draw(box((-0.8, -0.5), (2.0, 1.6)), invisible);
draw(conic(A, B, C, D, E), linewidth(0.5mm));
draw(A--B--C--cycle, grey);
dot("$A$", A, S); dot("$B$", B, W); dot("$C$", C, SW); dot("$D$", D, NW); dot("$E$", E, NE);
ASY
{ echo 'figure{width = "12cm"}'; cat "$src/examples/buimov/07_shaded_surface.lua"; } > "$tmp/surface.lua"
cat > "$tmp/surface.asy" <<'ASY'
import graph3;
settings.render = 0;
size(12cm);
currentprojection = orthographic(4, 2, 3);
currentlight = light((1, -1, 3));
real f(pair z) { return 0.5 * sin(3 * z.x) * cos(2 * z.y); }
draw(surface(f, (-1, -1), (1, 1), nx = 40, Spline), white, meshpen = black);
label("$z = 0.5 \sin 3x \cos 2y$", (0, 0, -0.9));
ASY

ms() { echo $(( ($(date +%s%N) - $1) / 1000000 )); }
best() {  # best NAME ARGS...: the best of 3 whole runs in ms
    b=""
    for _ in 1 2 3; do
        t0=$(date +%s%N)
        (cd "$tmp" && "$pc" "$@" > /dev/null) || exit 1
        t=$(ms "$t0")
        [ -z "$b" ] || [ "$t" -lt "$b" ] && b=$t
    done
    echo "$b"
}
for fig in conic surface; do
    pdf=$(best "$fig.lua" -o "$fig.pdf")
    png=$(best "$fig.lua" --dpi 300 -o "$fig.png")
    line="$fig: pointcalc PDF $pdf ms, 300-dpi PNG $png ms"
    if command -v asy > /dev/null; then
        t0=$(date +%s%N)
        (cd "$tmp" && asy -f pdf "$fig.asy" > /dev/null 2>&1) || echo "asy failed on $fig" >&2
        a=$(ms "$t0")
        line="$line; Asymptote PDF $a ms ($(awk "BEGIN { printf \"%.0f\", $a / $pdf }")x the pointcalc PDF)"
    fi
    echo "$line"
done

# the whole gallery, both looks, on all cores
find "$src/examples" -name '*.lua' | sort > "$tmp/list"
n=$(wc -l < "$tmp/list")
t0=$(date +%s%N)
xargs -P "$cores" -I{} sh -c 'cd "$1" && "$2" "$3" -o "$(basename "$3" .lua).png" -o "$(basename "$3" .lua).svg" >/dev/null 2>&1' _ "$tmp" "$pc" {} < "$tmp/list"
vga=$(ms "$t0")
t0=$(date +%s%N)
xargs -P "$cores" -I{} sh -c 'cd "$1" && "$2" "$3" --print -o "$(basename "$3" .lua).png" -o "$(basename "$3" .lua).svg" -o "$(basename "$3" .lua).pdf" >/dev/null 2>&1' _ "$tmp" "$pc" {} < "$tmp/list"
print=$(ms "$t0")
echo "gallery: $n scripts on $cores cores: VGA look PNG + SVG $vga ms; print look PNG + SVG + PDF $print ms"
