#!/bin/sh
# The label audit (tests/tools/label_audit.py) on figures with known faults, and automatic
# placement passing it: labels given directions that overlap, run off the picture and sit
# across a line are counted; the same labels without directions give 0, 0, 0.
. "$(dirname "$0")/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
command -v python3 >/dev/null || { echo "no python3: skipped"; exit 77; }
audit="$PC_SOURCE_DIR/tests/tools/label_audit.py"

cat > fixed.lua <<'LUA'
line(P(0, 200), P(639, 200))          -- a line the labels below may sit across
label("across", P(300, 205), "se")     -- its cell rows 208..223 miss the line: not crossed
label("on it", P(100, 195), "se")      -- rows 198..213: the line at 200 crosses it
label("N", P(400, 100), "ne")
label("T", P(402, 102), "ne")          -- overlaps N
label("off", P(630, 300), "e")         -- runs off the right edge
LUA
run "$POINTCALC" fixed.lua -o fixed.svg
expect_rc 0 "the faulty figure renders"
run python3 "$audit" fixed.svg
expect_rc 0 "the audit runs"
expect_in out.txt "labels 5 overlapping_pairs 1 outside 1 crossed 1" "the faults counted"

sed 's/, "[a-z]*")/)/' fixed.lua > auto.lua
run "$POINTCALC" auto.lua -o auto.svg
expect_rc 0 "the automatic figure renders"
run python3 "$audit" --each auto.svg
expect_in out.txt "labels 5 overlapping_pairs 0 outside 0 crossed 0" "automatic placement passes"

# the print look's SVG (width and height in pt, a viewBox, labels as <tspan> runs): the same
# faults counted in its own units, and automatic placement passing there too
run "$POINTCALC" fixed.lua --print -o fixed_print.svg
expect_rc 0 "the faulty figure in the print look"
expect_in fixed_print.svg 'width="480.000pt" height="360.000pt" viewBox="0 0 480.000 360.000"' "a print-look SVG"
run python3 "$audit" fixed_print.svg
expect_rc 0 "the audit reads the print look"
# (crossed 0: "on it" keeps its side and gap with its print box, whose halo and the font's
# leading put the glyphs' tops 2 pt under the line)
expect_in out.txt "labels 5 overlapping_pairs 1 outside 1 crossed 0" "the print look's faults counted"
run "$POINTCALC" auto.lua --print -o auto_print.svg
run python3 "$audit" auto_print.svg
expect_in out.txt "labels 5 overlapping_pairs 0 outside 0 crossed 0" "automatic placement passes in the print look"
finish
