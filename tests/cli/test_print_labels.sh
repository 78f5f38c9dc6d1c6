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
finish
