#!/bin/sh
# Benchmark of the print look.  Two figures, each as PDF and as a 300-dpi PNG, 12 cm wide,
# whole processes, against the same figures in Asymptote (`asy -f pdf`) in the same run:
#   - the conic through five points A..E with its labels (Konopatsky §2.1.4; Asymptote's
#     geometry module: conic(A, B, C, D, E));
#   - the 40 x 40 shaded surface of examples/buimov/07_shaded_surface.lua (Asymptote's
#     surface(f, ..., nx = 40, Spline) drawn white with a black mesh, render = 0: vector).
# Each: the best of 3 runs (Asymptote: of 2), wall clock and CPU time (user + system, which a
# machine shared with other work disturbs much less), through /usr/bin/time.  Then the whole
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
best() {  # best N CMD...: "WALL CPU" in ms, each the least of N whole runs
    n=$1; shift
    for _ in $(seq "$n"); do
        (cd "$tmp" && /usr/bin/time -f "%e %U %S" -o "$tmp/t" "$@" > /dev/null 2>&1) || echo "failed: $*" >&2
        tail -n 1 "$tmp/t"
    done | awk '{ w = $1 * 1000; c = ($2 + $3) * 1000
                  if (NR == 1 || w < bw) bw = w; if (NR == 1 || c < bc) bc = c }
                END { printf "%.0f %.0f", bw, bc }'
}
show() { echo "$1" | awk '{ printf "%s ms (CPU %s ms)", $1, $2 }'; }
for fig in conic surface; do
    pdf=$(best 3 "$pc" "$fig.lua" -o "$fig.pdf")
    png=$(best 3 "$pc" "$fig.lua" --dpi 300 -o "$fig.png")
    line="$fig: pointcalc PDF $(show "$pdf"), 300-dpi PNG $(show "$png")"
    if command -v asy > /dev/null; then
        a=$(best 2 asy -f pdf "$fig.asy")
        line="$line; Asymptote PDF $(show "$a"): $(echo "$a $pdf" | awk '{ printf "%.0fx wall, %.0fx CPU", $1 / $3, $2 / $4 }')"
    fi
    echo "$line"
done

# the whole gallery, both looks, on all cores
find "$src/examples" -name '*.lua' | sort > "$tmp/list"
n=$(wc -l < "$tmp/list")
# one script: render.sh LOOK SCRIPT writes GROUP_NAME.png/.svg (and .pdf in the print look)
cat > "$tmp/render.sh" <<'SH'
out="$(basename "$(dirname "$2")")_$(basename "$2" .lua)"
if [ "$1" = vga ]; then "$PC" "$2" -o "$out.png" -o "$out.svg"
else "$PC" "$2" --print -o "$out.png" -o "$out.svg" -o "$out.pdf"; fi > /dev/null 2>&1
SH
gallery() {  # gallery LOOK: every script on all cores: "WALL CPU" in ms
    (cd "$tmp" && PC="$pc" /usr/bin/time -f "%e %U %S" -o "$tmp/t" \
        xargs -P "$cores" -n 1 sh "$tmp/render.sh" "$1" < "$tmp/list")
    tail -n 1 "$tmp/t" | awk '{ printf "%.0f %.0f", $1 * 1000, ($2 + $3) * 1000 }'
}
vga=$(gallery vga)
print=$(gallery print)
echo "gallery: $n scripts on $cores cores: VGA look PNG + SVG $(show "$vga"); print look PNG + SVG + PDF $(show "$print")"
