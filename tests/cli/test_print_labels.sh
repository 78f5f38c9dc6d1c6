#!/bin/sh
# Automatic labels in the print look agree across outputs: one run writes the PDF and the SVG;
# each label's left end in the PDF (pdftotext -bbox) is the SVG <tspan>'s x within 0.01 pt (the
# same Pango boxes placed them); the same figure at 300 dpi is the 10 cm page in pixels.
. "$(dirname "$0")/lib.sh"
command -v pdftotext >/dev/null || { echo "no pdftotext: skipped"; exit 77; }

cat > fig.lua <<'LUA'
figure{width = "10cm", size = 10}
window(0, 0, 4, 3)
local A, B, C, D = P(0.5, 0.5), P(0.6, 0.6), P(3.5, 0.5), P(2, 2.5)
path{A, C, D, close = true}
line(B, D)
for name, p in pairs{Q = A, W = B, Y = C, Z = D} do mark(p) label(name, p) end
LUA
run "$POINTCALC" fig.lua -o fig.pdf -o fig.svg
expect_rc 0 "the figure renders as PDF and SVG"
pdftotext -bbox fig.pdf - > bbox.txt
for name in Q W Y Z; do
    pdf=$(sed -n "s/.*xMin=\"\([0-9.]*\)\".*>$name<\/word>.*/\1/p" bbox.txt)
    svg=$(grep -o "<tspan x=\"[0-9.]*\" y=\"[0-9.]*\">$name<" fig.svg | sed "s/<tspan x=\"\([0-9.]*\)\".*/\1/")
    checks=$((checks + 1))
    awk -v a="$pdf" -v b="$svg" 'BEGIN { d = a - b; exit !(a != "" && b != "" && d < 0.01 && d > -0.01) }' ||
        fail "label $name: the PDF has it at x = '$pdf' pt, the SVG at '$svg'"
done
run "$POINTCALC" fig.lua --dpi 300 -o fig.png
expect_rc 0 "the 300-dpi PNG"
run sh -c "file fig.png"
expect_in out.txt "1181 x 886" "10 cm at 300 dpi"

# figure{} without a window: world units with y up, framed to what is drawn at true shape
# (the 4 x 3 triangle's legs keep 4:3 and C is above A); a SCREEN keeps the pixels
cat > frame.lua <<'LUA'
figure{width = "10cm"}
path({P(0, 0), P(4, 0), P(0, 3)}, {closed = true})
label("A", P(0, 0)) label("B", P(4, 0)) label("C", P(0, 3))
LUA
run "$POINTCALC" frame.lua -o frame.svg
expect_rc 0 "a figure without a window"
set -- $(grep -o '<path d="M[0-9.]* [0-9.]*L[0-9.]* [0-9.]*L[0-9.]* [0-9.]*Z"' frame.svg | tr 'MLZ"' '    ')
checks=$((checks + 1))
awk -v ax="$3" -v ay="$4" -v bx="$5" -v by="$6" -v cx="$7" -v cy="$8" 'BEGIN {
    w = bx - ax; h = ay - cy; r = w / h - 4 / 3
    exit !(ay == by && ax == cx && h > 0 && r < 1e-3 && r > -1e-3 && w > 200 && ax > 5) }' ||
    fail "the framed triangle: got '$*'"
printf 'screen(12)\nfigure{width = "480pt"}\nline(0, 0, 639, 479)\n' > pixels.lua
run "$POINTCALC" pixels.lua -o pixels.svg
expect_rc 0 "a SCREEN 12 figure"
expect_in pixels.svg '<path d="M0.375 0.375L479.625 359.625"' "SCREEN 12 keeps its pixels"
printf 'line(0, 0, 639, 479)\n' > vga.lua
run "$POINTCALC" vga.lua --size 480pt -o vga.svg
expect_in vga.svg '<path d="M0.375 0.375L479.625 359.625"' "--size on a VGA script keeps its pixels"
finish
