# The print look from the command line: PDF (valid, fonts embedded and subset, text that comes
# back out), EPS (Ghostscript renders it), PNG at a size and resolution, the SVG's text, the
# three renderings agreeing, the VGA look unchanged without the options, and every usage error.
. "$(dirname "$0")/lib.sh"
for tool in pdfinfo pdffonts pdftotext pdftoppm gs rsvg-convert python3; do
    command -v $tool >/dev/null || { echo "SKIP: $tool is not installed (./setup.sh installs it)"; exit 77; }
done
inkdiff="python3 $PC_SOURCE_DIR/tests/cli/inkdiff.py"

cat > fig.lua <<'LUA'
window(-1, -1, 3, 2)
pen "main" line(P(0, 0), P(2, 1))
pen "thin" circle(P(1, 0.5), 0.5)
pen "hidden" line(P(0, 1), P(2, 0))
pen()
label("$A_1$", P(0, 0), "sw")
label("$\\varphi$ угол", P(2, 1), "ne")
label("$\\overline{AB}$ $M''$", P(1, 1.5), "n")
LUA

# PDF: valid, the fonts embedded and subset, the labels' text (Cyrillic, the math letters)
run "$POINTCALC" fig.lua -o fig.pdf; expect_rc 0 "write a PDF"
run pdfinfo fig.pdf; expect_rc 0 "pdfinfo reads the PDF"; tr -s ' ' < out.txt > info.txt
expect_in info.txt "Pages: 1" "one page"
expect_in info.txt "Page size: 480 x 360 pts" "the canvas at 96 px to the inch"
run pdffonts fig.pdf; expect_rc 0 "pdffonts"
expect_in out.txt "CMUSerif-Italic" "the serif's italic for the math letters"
checks=$((checks + 1))
awk 'NR > 2 && ($(NF-4) != "yes" || $(NF-3) != "yes") { bad = 1 } END { exit bad }' out.txt ||
    fail "every font embedded and subset: $(cat out.txt)"
run pdftotext fig.pdf -; expect_rc 0 "pdftotext"
expect_in out.txt "угол" "Cyrillic comes back out"
expect_in out.txt "φ" "the Greek letter"
expect_in out.txt "A1" "A with its subscript"
expect_in out.txt "AB" "the overlined letters"

# EPS and PS: PostScript that Ghostscript renders
run "$POINTCALC" fig.lua -o fig.eps -o fig.ps; expect_rc 0 "write EPS and PS"
expect_in fig.eps "%!PS-Adobe-3.0 EPSF-3.0" "an EPS header"
expect_in fig.eps "%%BoundingBox: 0 0 480 360" "its bounding box"
run gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=ppmraw -r96 -dEPSCrop -sOutputFile=eps.ppm fig.eps
expect_rc 0 "Ghostscript renders the EPS"; expect_file eps.ppm "the EPS rendered"

# a size and a resolution: 12 cm at 300 dpi is 1417 pixels wide
run "$POINTCALC" fig.lua --size 12cm --dpi 300 -o big.png; expect_rc 0 "--size --dpi"
expect_eq "$(od -An -tu1 -j16 -N4 big.png | tr -s ' ')" " 0 0 5 137" "1417 px wide (0x0589)"
run "$POINTCALC" fig.lua --size 12cmx6cm -o wide.pdf; expect_rc 0 "--size WxH"
run pdfinfo wide.pdf; tr -s ' ' < out.txt > info.txt
expect_in info.txt "Page size: 340.157 x 170.079 pts" "12 cm by 6 cm"

# the three renderings of one figure agree within a few pixels of ink
run "$POINTCALC" fig.lua --print -o p.png -o p.svg -o p.pdf; expect_rc 0 "--print PNG, SVG and PDF"
expect_in p.svg "<tspan" "the print SVG keeps the labels as text"
expect_in p.svg "font-family=\"CMU Serif\"" "in the figure's font"
run pdftoppm -r 96 -singlefile p.pdf pdf; expect_rc 0 "pdftoppm"
run rsvg-convert -o svg.png p.svg; expect_rc 0 "rsvg-convert"
run $inkdiff p.png pdf.ppm 2; expect_rc 0 "PNG and PDF agree ($(cat out.txt))"
run $inkdiff p.png svg.png 2; expect_rc 0 "PNG and SVG agree ($(cat out.txt))"
run $inkdiff p.png eps.ppm 2; expect_rc 0 "PNG and EPS agree ($(cat out.txt))"

# without the options, PNG and SVG stay the VGA look: an 8-bit palette PNG of 640x480
run "$POINTCALC" fig.lua -o vga.png -o vga.svg; expect_rc 0 "the VGA look"
expect_eq "$(od -An -tu1 -j16 -N10 vga.png | tr -s ' ')" " 0 0 2 128 0 0 1 224 4 3" "a 640x480 palette PNG of 16 colours"
expect_in vga.svg "font-family=\"monospace\"" "the VGA SVG's text"

# figure{} in a script gives the print look; the command line overrides its dpi
printf 'figure{width = "5cm", dpi = 100}\nline(0, 0, 639, 479)\n' > f.lua
run "$POINTCALC" f.lua -o f.png; expect_rc 0 "figure{}"
expect_eq "$(od -An -tu1 -j16 -N4 f.png | tr -s ' ')" " 0 0 0 197" "5 cm at 100 dpi: 197 px"
run "$POINTCALC" f.lua --dpi 200 -o f.png; expect_rc 0 "--dpi over figure{}"
expect_eq "$(od -An -tu1 -j16 -N4 f.png | tr -s ' ')" " 0 0 1 138" "5 cm at 200 dpi: 394 px"

# errors
run "$POINTCALC" fig.lua --size 12; expect_rc 2 "--size without a unit"
expect_in err.txt "--size: the length '12' needs a unit (cm, mm, in, pt or px)" "--size message"
run "$POINTCALC" fig.lua --size 12cmx; expect_rc 2 "--size without a height"
run "$POINTCALC" fig.lua --dpi 0; expect_rc 2 "--dpi 0"
expect_in err.txt "--dpi needs a resolution 10..2400" "--dpi message"
run "$POINTCALC" fig.lua --dpi; expect_rc 2 "--dpi without a value"
printf 'label("$A_{1$", 10, 10)\n' > bad.lua
run "$POINTCALC" bad.lua -o bad.pdf; expect_rc 1 "a bad math label"
expect_in err.txt "bad.lua:1: label: label '\$A_{1\$': unbalanced '{' at character 4" "names the label"
expect_no_file bad.pdf "no PDF for a failed script"
printf 'label("x", 10, 10, {font = "Nonexistent Face"})\n' > font.lua
run "$POINTCALC" font.lua -o font.pdf; expect_rc 1 "a missing font"
expect_in err.txt "font 'Nonexistent Face' is not installed" "names the font"
# no fonts at all (an empty fontconfig): the error names the Debian package, no file is left
printf '<?xml version="1.0"?>\n<fontconfig></fontconfig>\n' > empty.conf
FONTCONFIG_FILE="$PWD/empty.conf" run "$POINTCALC" fig.lua -o nofont.pdf; expect_rc 1 "no fonts installed"
expect_in err.txt "cannot write 'nofont.pdf': font 'serif' (CMU Serif) is not installed: install the Debian package fonts-cmu" "names fonts-cmu"
expect_no_file nofont.pdf "no PDF without its font"
# a shaded surface in a PDF: its quads are tiles, so no seam of paper shows between them, where
# two fills of one colour side by side (fill) show one along their shared diagonal
shades() {  # shades PGM X0 X1 Y0 Y1: the grey levels in the box, "level count" each
    od -An -v -tu1 -j 15 "$1" | tr -s ' \n' '\n' | grep . |
        awk -v x0=$2 -v x1=$3 -v y0=$4 -v y1=$5 '{ i = NR - 1; x = i % 640; y = int(i / 640)
            if (x >= x0 && x <= x1 && y >= y0 && y <= y1) n[$0]++ } END { for (k in n) print k, n[k] }'
}
cat > tiles.lua <<'EOF'
camera(map.matrix({{71, -71, 0, 320}, {-71, -71, 0, 240}, {0, 0, 0, 1}}))
surface.bilinear(P(-1, -1, 0), P(1, -1, 0), P(-1, 1, 0), P(1, 1, 0)):shade{nu = 5, nv = 5, color = "#404040"}
EOF
cat > fills.lua <<'EOF'
fill({P(260, 180), P(380, 180), P(380, 300)}, "#404040")
fill({P(260, 180), P(380, 300), P(260, 300)}, "#404040")
EOF
run "$POINTCALC" tiles.lua -o tiles.pdf; expect_rc 0 "a shaded surface to PDF"
run "$POINTCALC" fills.lua -o fills.pdf; expect_rc 0 "two fills to PDF"
pdftoppm -r 96 -gray -singlefile tiles.pdf tiles && pdftoppm -r 96 -gray -singlefile fills.pdf fills
expect_eq "$(shades tiles.pgm 300 340 200 280)" "64 3321" "the shaded quads are one grey, no seams"
expect_eq "$(shades fills.pgm 270 370 190 290 | wc -l | tr -d ' ')" "2" "two plain fills show their seam"

finish
