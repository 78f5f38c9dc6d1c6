# What real programs meet, part three: a text-mode program's picture (the 80x25 screen drawn in
# the VGA 8x16 font, COLOR, LOCATE, CLS, wrapping, scrolling, WIDTH 40 and 50 lines), the screen
# written when a runtime error stops a program, RETURN line, PRINT's items printed one by one
# under an error trap, and the end pixels of CIRCLE's arcs.  Exact pixels and exact output.
# Code page 437's CHR$(219) is a full block: its cell is all ink, so its pixels are exact.
. "$(dirname "$0")/lib.sh"

px320() { od -An -tx1 -j $((15 + ($3 * 320 + $2) * 3)) -N 3 "$1" | tr -d ' \n'; }

# ---- the text screen ---------------------------------------------------------------------
cat > text0.bas <<'EOF'
COLOR 14, 1: CLS
LOCATE 3, 10: PRINT CHR$(219);
COLOR 12, 0
LOCATE 5, 80: PRINT CHR$(219); CHR$(219)
PRINT "A"; CHR$(0); "B"
PRINT STRING$(80, 219)
PRINT "next"
EOF
run "$POINTCALC" text0.bas -o text0.ppm
expect_rc 0 "text mode program"
expect_eq "$(head -c 15 text0.ppm | tr '\n' ' ')" "P6 640 400 255 " "80x25 text mode writes 640x400"
expect_eq "$(ppm_pixel text0.ppm 300 300)" "0000aa" "COLOR 14, 1: CLS fills the screen with blue"
expect_eq "$(ppm_pixel text0.ppm 72 32)" "ffff55" "LOCATE 3, 10: the block's cell starts at (72, 32)"
expect_eq "$(ppm_pixel text0.ppm 79 47)" "ffff55" "... and ends at (79, 47), yellow"
expect_eq "$(ppm_pixel text0.ppm 80 40)" "0000aa" "the next cell: blue background"
expect_eq "$(ppm_pixel text0.ppm 71 40)" "0000aa" "the cell before: blue background"
expect_eq "$(ppm_pixel text0.ppm 636 70)" "ff5555" "LOCATE 5, 80: light red at the last column"
expect_eq "$(ppm_pixel text0.ppm 3 86)" "ff5555" "the second block wrapped to row 6, column 1"
expect_eq "$(ppm_pixel text0.ppm 12 100)" "000000" "CHR\$(0) is a blank cell (row 7, column 2)"
expect_eq "$(ppm_pixel text0.ppm 639 120)" "ff5555" "80 blocks fill row 8"
expect_eq "$(ppm_pixel text0.ppm 100 136)" "0000aa" "a full row does not leave an empty row: row 9 is 'next'"
expect_eq "$(ppm_pixel text0.ppm 0 152)" "0000aa" "row 10 blank, as CLS left it"
# standard output stays the transcript it was (LOCATE to another row starts a new line)
{ printf '\333\n\333\333\nA\000B\n'; for i in $(seq 80); do printf '\333'; done; printf '\nnext\n'; } > want.txt
check
cmp -s want.txt out.txt || fail "the transcript on standard output: $(od -An -c out.txt | head -3)"

# code page 437's double lines and half blocks in the VGA BIOS's 8x16 font: CHR$(205) has ink
# on rows 5 and 7 of its cell, the lower on the row of CHR$(196)'s single line (so they join);
# CHR$(220) is the lower half (rows 7..15), CHR$(222) the right half (columns 4..7), not the
# replacement glyph
printf 'PRINT CHR$(205); CHR$(220); CHR$(222); CHR$(196)\n' > boxes.bas
run "$POINTCALC" boxes.bas -o boxes.ppm
expect_rc 0 "box drawings"
expect_eq "$(ppm_pixel boxes.ppm 3 5)$(ppm_pixel boxes.ppm 3 6)$(ppm_pixel boxes.ppm 3 7)" \
    "aaaaaa000000aaaaaa" "CHR\$(205) is a double line (rows 5 and 7)"
expect_eq "$(ppm_pixel boxes.ppm 27 6)$(ppm_pixel boxes.ppm 27 7)" "000000aaaaaa" "CHR\$(196) a single one (row 7)"
expect_eq "$(ppm_pixel boxes.ppm 8 15)$(ppm_pixel boxes.ppm 15 7)$(ppm_pixel boxes.ppm 8 6)" \
    "aaaaaaaaaaaa000000" "CHR\$(220) is the lower half of its cell (rows 7..15)"
# the control bytes PRINT shows are the BIOS's pictures: CHR$(3) the heart (its row 4 .##.##..,
# row 5 #######.), CHR$(0) a blank cell; the transcript keeps the bytes
printf 'PRINT CHR$(0); CHR$(3)\n' > heart.bas
run "$POINTCALC" heart.bas -o heart.ppm
expect_rc 0 "a heart"
expect_eq "$(ppm_pixel heart.ppm 8 4)$(ppm_pixel heart.ppm 9 4)$(ppm_pixel heart.ppm 8 5)$(ppm_pixel heart.ppm 15 5)" \
    "000000aaaaaaaaaaaa000000" "CHR\$(3) is the BIOS's heart"
expect_eq "$(ppm_pixel heart.ppm 3 5)$(ppm_pixel heart.ppm 4 8)" "000000000000" "CHR\$(0) is a blank cell"
# CHR$(7), the bell, takes no cell: the two blocks around it are side by side, on a text screen
# and on a graphics one; the transcript keeps the byte
printf 'PRINT CHR$(219); CHR$(7); CHR$(219)\n' > bell.bas
run "$POINTCALC" bell.bas -o bell.ppm
expect_rc 0 "the bell"
expect_eq "$(ppm_pixel bell.ppm 8 15)$(ppm_pixel bell.ppm 15 0)$(ppm_pixel bell.ppm 20 8)" \
    "aaaaaaaaaaaa000000" "CHR\$(7) takes no cell on a text screen"
expect_eq "$(od -An -c out.txt | tr -d ' \n')" "333\a333\n" "the transcript keeps the bell"
printf 'SCREEN 12\nPRINT CHR$(219); CHR$(7); CHR$(219)\n' > bell12.bas
run "$POINTCALC" bell12.bas -o bell12.ppm
expect_rc 0 "the bell on a graphics screen"
expect_eq "$(ppm_pixel bell12.ppm 8 15)$(ppm_pixel bell12.ppm 20 8)" "ffffff000000" \
    "CHR\$(7) takes no cell on a graphics screen"
expect_eq "$(ppm_pixel boxes.ppm 16 0)$(ppm_pixel boxes.ppm 20 0)$(ppm_pixel boxes.ppm 23 15)" \
    "000000aaaaaaaaaaaa" "CHR\$(222) is the right half of its cell"

# scrolling: 30 lines on 25 rows, the cursor on a new last row: rows 1..24 show lines 7..30
cat > scroll.bas <<'EOF'
FOR i = 1 TO 30
  IF i = 7 THEN PRINT CHR$(219) ELSE PRINT i
NEXT
EOF
run "$POINTCALC" scroll.bas -o scroll.ppm
expect_rc 0 "scrolling program"
expect_eq "$(ppm_pixel scroll.ppm 4 8)" "aaaaaa" "line 7 scrolled up to row 1 (grey 7 on black)"
expect_eq "$(ppm_pixel scroll.ppm 4 392)" "000000" "the last row is empty after the last PRINT's newline"
expect_eq "$(wc -l < out.txt | tr -d " ")" 30 "all 30 lines on standard output"

# WIDTH 40: 320x400; WIDTH 80, 50: the 8x8 font, 640x400
printf 'WIDTH 40\nLOCATE 1, 40: PRINT CHR$(219);\n' > w40.bas
run "$POINTCALC" w40.bas -o w40.ppm
expect_eq "$(head -c 15 w40.ppm | tr '\n' ' ')" "P6 320 400 255 " "WIDTH 40 writes 320x400"
expect_eq "$(px320 w40.ppm 319 15)" "aaaaaa" "WIDTH 40: column 40 is the last cell"
printf 'WIDTH 80, 50\nLOCATE 50, 1: PRINT CHR$(219);\n' > w50.bas
run "$POINTCALC" w50.bas -o w50.ppm
expect_eq "$(ppm_pixel w50.ppm 0 392)" "aaaaaa" "WIDTH 80, 50: row 50 is 8 pixels high, from y 392"
expect_eq "$(ppm_pixel w50.ppm 0 391)" "000000" "WIDTH 80, 50: row 49 untouched"
printf 'WIDTH , 43\nLOCATE 43, 80: PRINT CHR$(219);\n' > w43.bas
run "$POINTCALC" w43.bas -o w43.ppm
expect_eq "$(head -c 15 w43.ppm | tr '\n' ' ')" "P6 640 350 255 " "WIDTH , 43 writes 640x350"
expect_eq "$(ppm_pixel w43.ppm 639 343)" "aaaaaa" "WIDTH , 43: row 43 ends at y 343"
expect_eq "$(ppm_pixel w43.ppm 639 344)" "000000" "WIDTH , 43: the last 6 lines stay black"
printf 'WIDTH 80, 30\n' > w30.bas
run "$POINTCALC" w30.bas
expect_rc 1 "WIDTH 80, 30 in text mode"
expect_in err.txt "w30.bas:1: Illegal function call" "text mode has 25, 43 and 50 lines"
# SVG and PNG of the same screen
run "$POINTCALC" text0.bas -o text0.svg -o text0.png
expect_rc 0 "text mode to SVG and PNG"
expect_eq "$(head -c 8 text0.png | od -An -c | tr -d ' ')" "211PNG\r\n032\n" "a PNG"
expect_in text0.svg 'width="640"' "the SVG is 640 wide"
# a program without -o writes no picture, as before
run "$POINTCALC" text0.bas
expect_eq "$(ls *.png | wc -l | tr -d ' ')" 1 "no picture without -o"

# a graphics program that returns to SCREEN 0 at its end keeps its drawing as the picture; one
# that prints in text mode after it gives the text screen
printf 'PRINT "title"\nSCREEN 12\nLINE (0, 0)-(100, 0), 14\nSCREEN 0\nWIDTH 80\n' > back0.bas
run "$POINTCALC" back0.bas -o back0.ppm
expect_eq "$(ppm_pixel back0.ppm 50 0)" "ffff55" "SCREEN 0 at the end: the drawing stays the picture"
printf 'SCREEN 12\nLINE (0, 0)-(100, 0), 14\nSCREEN 0\nPRINT CHR$(219)\n' > back1.bas
run "$POINTCALC" back1.bas -o back1.ppm
expect_eq "$(head -c 15 back1.ppm | tr '\n' ' ')" "P6 640 400 255 " "text printed after SCREEN 0: the text screen"

# ---- a runtime error writes the screen as it stood ---------------------------------------
printf 'SCREEN 12\nLINE (0, 0)-(10, 0), 14\nx = 1 / 0\nLINE (0, 5)-(10, 5), 14\n' > stop.bas
run "$POINTCALC" stop.bas -o stop.ppm
expect_rc 1 "a runtime error"
expect_eq "$(head -n 1 err.txt)" "stop.bas:3: Division by zero" "the error with its line"
expect_in err.txt "writing the screen as it stood when the program was stopped" "says why"
expect_eq "$(ppm_pixel stop.ppm 5 0)" "ffff55" "the line drawn before the error"
expect_eq "$(ppm_pixel stop.ppm 5 5)" "000000" "nothing after it"
printf 'PRINT CHR$(219)\nERROR 5\n' > stop0.bas
run "$POINTCALC" stop0.bas -o stop0.ppm
expect_rc 1 "a runtime error in text mode"
expect_eq "$(head -n 1 err.txt)" "stop0.bas:2: Illegal function call" "ERROR 5 with its line"
expect_eq "$(ppm_pixel stop0.ppm 3 3)" "aaaaaa" "the text screen as it stood"

# ---- RETURN line -------------------------------------------------------------------------
cat > retline.bas <<'EOF'
10 PRINT "start"
20 GOSUB 100
30 PRINT "not reached"
40 END
100 PRINT "in sub"
110 RETURN 200
200 PRINT "at 200"
210 GOSUB 300
220 PRINT "back"
230 END
300 PRINT "plain": RETURN
EOF
run "$POINTCALC" retline.bas
expect_rc 0 "RETURN line"
expect_eq "$(cat out.txt | tr '\n' '|')" "start|in sub|at 200|plain|back|" "RETURN 200 goes on at 200"
printf '10 GOSUB 20\n20 RETURN 99\n' > retbad.bas
run "$POINTCALC" retbad.bas
expect_rc 1 "RETURN to a missing line"
expect_eq "$(head -n 1 err.txt)" "retbad.bas:2: Label not defined" "RETURN 99: Label not defined"

# ---- PRINT item by item under RESUME NEXT ------------------------------------------------
cat > printres.bas <<'EOF'
ON ERROR GOTO h
PRINT "a"; 1; 1 / 0; "after"
PRINT "end"
END
h: PRINT "[err"; ERR; "]": RESUME NEXT
EOF
run "$POINTCALC" printres.bas
expect_rc 0 "PRINT with RESUME NEXT"
expect_eq "$(cat out.txt | tr '\n' '|')" "a 1 [err 11 ]|end|" "the items before the failing one are printed"

# ---- CIRCLE's arc ends -------------------------------------------------------------------
printf 'SCREEN 12\nCIRCLE (320, 240), 100, 15, 1.5708, 3.1416\nCIRCLE (320, 240), 50, 15, 0, 1.5708\n' > arcs.bas
run "$POINTCALC" arcs.bas -o arcs.ppm
expect_rc 0 "arcs"
expect_eq "$(ppm_pixel arcs.ppm 320 140)" "ffffff" "an arc from 1.5708 lights its first pixel"
expect_eq "$(ppm_pixel arcs.ppm 220 240)" "ffffff" "... and its last, at 3.1416"
expect_eq "$(ppm_pixel arcs.ppm 320 190)" "ffffff" "an arc to 1.5708 lights its last pixel"
expect_eq "$(ppm_pixel arcs.ppm 321 140)" "000000" "nothing before the start"
finish
