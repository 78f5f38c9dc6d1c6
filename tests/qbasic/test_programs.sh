# The project's own QBasic programs (tests/qbasic/progs/*.bas): each must run without error and
# PRINT exactly its .out file.  They cover PRINT formatting, the float32 FOR loop counts, the RND
# sequence, operators and their precedence, variables and types, control flow (IF, GOTO, WHILE,
# DO, EXIT, SELECT CASE), DATA/READ/RESTORE, SUB/FUNCTION/DEF FN/GOSUB, strings, and the drawing
# statements (through POINT).
. "$(dirname "$0")/lib.sh"

n=0
cp "$QB_DIR"/progs/*.bas .     # all of them: chain.bas runs chain_next.bas
for bas in "$QB_DIR"/progs/*.bas; do
    name=$(basename "$bas" .bas)
    # a program that expects a person reads its answers from NAME.in (else no input at all)
    input=/dev/null
    [ -f "$QB_DIR/progs/$name.in" ] && input="$QB_DIR/progs/$name.in"
    run "$POINTCALC" "$name.bas" -o "$name.ppm" < "$input"
    expect_rc 0 "$name"
    cp err.txt "$name.err"
    check
    if ! diff -u "$QB_DIR/progs/$name.out" out.txt >diff.txt; then
        fail "$name: output differs from $name.out:"
        cat diff.txt >&2
    fi
    n=$((n + 1))
done
expect_eq "$([ "$n" -ge 10 ] && echo yes)" yes "at least 10 programs found in $QB_DIR/progs"

# the same pictures through the writers: graphics.bas drew (75, 55) inside a BF box in magenta
# 5, the circle through (250, 200) in yellow 14 and the painted disc (200, 200) in blue 1.  (Its
# PRINTs now draw their text into the picture, as QBasic does, over the dots it put at (10, 10)
# and (20, 21) in the first two text rows: text.bas checks those cells.)
expect_eq "$(ppm_pixel graphics.ppm 250 200)" "ffff55" "PPM pixel (250,200) = colour 14"
expect_eq "$(ppm_pixel graphics.ppm 75 55)" "aa00aa" "PPM pixel (75,55) = colour 5"
expect_eq "$(ppm_pixel graphics.ppm 200 200)" "0000aa" "PPM pixel (200,200) = colour 1"
expect_eq "$(ppm_pixel graphics.ppm 11 10)" "000000" "PPM pixel (11,10) = background"
# graphics2.bas redefined attribute 1 as PALETTE 1, 63 + 256 * 32 (6-bit red 63, green 32)
expect_eq "$(ppm_pixel graphics2.ppm 5 5)" "ff8200" "PALETTE reaches the written picture"
# the picture written is the page shown: modes.bas (SCREEN 7, 320x200) copied page 1's light
# red line (0, 150)-(50, 150) onto page 0, and printed text into its first rows
px320() { od -An -tx1 -j $((15 + ($3 * 320 + $2) * 3)) -N 3 "$1" | tr -d ' \n'; }
expect_eq "$(head -c 15 modes.ppm | tr '\n' ' ')" "P6 320 200 255 " "SCREEN 7 writes 320x200"
expect_eq "$(px320 modes.ppm 25 150)" "ff5555" "PCOPY 1, 0 shows page 1's line"
expect_eq "$(px320 modes.ppm 25 151)" "0000aa" "below the line: the background, blue after COLOR 10, 1"
# records.bas drew its triangle in yellow 14 and the moved centre (116.67, 111.67) in red 12
expect_eq "$(ppm_pixel records.ppm 150 150)" "ffff55" "records: the triangle's base"
expect_eq "$(ppm_pixel records.ppm 117 112)" "ff5555" "records: the centre moved by the SUB"
# tiles.bas ends in SCREEN 2 (640x200): the ellipse painted with CHR$(&H88) + CHR$(&H22)
expect_eq "$(head -c 15 tiles.ppm | tr '\n' ' ')" "P6 640 200 255 " "SCREEN 2 writes 640x200"
expect_eq "$(ppm_pixel tiles.ppm 320 100)" "ffffff" "tile row 0, x mod 8 = 0: on"
expect_eq "$(ppm_pixel tiles.ppm 321 100)" "000000" "tile row 0, x mod 8 = 1: off"
expect_eq "$(ppm_pixel tiles.ppm 322 101)" "ffffff" "tile row 1, x mod 8 = 2: on"
expect_eq "$(ppm_pixel tiles.ppm 500 145)" "ffffff" "DRAW A1 R24 in SCREEN 2: 10 pixels up"

# vga.bas (SCREEN 13) wrote DAC entries 1-3 through the ports: orange (63, 32, 0), dark blue
# (0, 0, 20), green (0, 40, 0), 6-bit levels widened as the VGA does (v * 4 + v \ 16); it
# POKEd pixels of colour 40 (the default DAC's red) into video memory at row 150
expect_eq "$(px320 vga.ppm 50 110)" "ff8200" "OUT &H3C9 changes the palette of the picture"
expect_eq "$(px320 vga.ppm 150 110)" "000051" "the DAC write index moves on: entry 2"
expect_eq "$(px320 vga.ppm 250 110)" "00a200" "the DAC write index moves on: entry 3"
expect_eq "$(px320 vga.ppm 25 150)" "ff0000" "POKE into &HA000 sets a pixel"
expect_eq "$(px320 vga.ppm 60 150)" "000000" "POKE: only the pixels written"
# vga12.bas: in SCREEN 12 DAC entry 6 is no attribute's (brown stays), entry 62 is attribute 14's
expect_eq "$(ppm_pixel vga12.ppm 50 110)" "aa5500" "SCREEN 12: attribute 6 shows DAC entry 20"
expect_eq "$(ppm_pixel vga12.ppm 150 110)" "8282ff" "SCREEN 12: attribute 14 shows DAC entry 62"

# the end of the input: INPUT with nothing left to read ends keyboard.bas at line 23, normally,
# saying so
expect_in keyboard.err "keyboard.bas:23: input ended (INPUT with no input left): the program is ended" \
    "INPUT at the end of the input"

# gwbasic.bas: the direct-mode commands between and after its numbered lines are skipped, each
# named on standard error
expect_in gwbasic.err 'gwbasic.bas:8: SAVE "GWDEMO.BAS",A: a GW-BASIC direct-mode command' \
    "a GW-BASIC SAVE line is named"
expect_eq "$(grep -c 'direct-mode command' gwbasic.err)" 3 "LIST, SAVE and RUN lines skipped"

# clock_env.bas: PALETTE USING p(0) gave attribute 1 red 63, attribute 2 green 63 and left
# attribute 4 (-1 in the array) its red 42
expect_eq "$(ppm_pixel clock_env.ppm 50 110)" "ff0000" "PALETTE USING: attribute 1"
expect_eq "$(ppm_pixel clock_env.ppm 150 110)" "00ff00" "PALETTE USING: attribute 2"
expect_eq "$(ppm_pixel clock_env.ppm 250 110)" "aa0000" "PALETTE USING: -1 leaves attribute 4"
# screen11.bas: SCREEN 11 is 640x480 in 2 colours; PALETTE 1, 42 made colour 1 red 42
expect_eq "$(head -c 15 screen11.ppm | tr '\n' ' ')" "P6 640 480 255 " "SCREEN 11 writes 640x480"
expect_eq "$(ppm_pixel screen11.ppm 30 30)" "aa0000" "SCREEN 11: colour 1 after PALETTE 1, 42"
# screen8.bas: SCREEN 8 is 640x200 in 16 colours; PALETTE 12, 2 made the box green, COLOR 15, 1
# the background blue; page 3's dot was copied onto page 0; text cells are 8x8 (row 25 at y 192)
px640() { od -An -tx1 -j $((15 + ($3 * 640 + $2) * 3)) -N 3 "$1" | tr -d ' \n'; }
expect_eq "$(head -c 15 screen8.ppm | tr '\n' ' ')" "P6 640 200 255 " "SCREEN 8 writes 640x200"
expect_eq "$(px640 screen8.ppm 100 60)" "00aa00" "SCREEN 8: the box's corner in attribute 12 = colour 2"
expect_eq "$(px640 screen8.ppm 140 79)" "0000aa" "SCREEN 8: beside the box, the background colour 1"
expect_eq "$(px640 screen8.ppm 600 150)" "55ff55" "SCREEN 8: PCOPY 3, 0 brought page 3's dot"
expect_eq "$(px640 screen8.ppm 420 120)" "ffff55" "SCREEN 8: the circle's right end at radius 100"
expect_eq "$(px640 screen8.ppm 608 192)" "ffffff" "SCREEN 8: E's top-left pixel in row 25, column 77"
expect_eq "$(px640 screen8.ppm 608 199)" "0000aa" "SCREEN 8: the cell's last line is blank"
expect_eq "$(px640 screen8.ppm 615 192)" "0000aa" "SCREEN 8: the cell's last column is blank"

# files.bas under the safe mode: without --allow the first OPEN is QBasic's Permission denied
# (70, which the program traps); with --allow of its folder it runs as before
cp "$QB_DIR/progs/files.bas" safe_files.bas
run "$POINTCALC" --safe safe_files.bas
expect_rc 0 "files.bas in the safe mode"
expect_eq "$(cat out.txt)" "error 70 " "the safe mode refuses the program's files: Permission denied"
run "$POINTCALC" --safe --allow "$WORK" safe_files.bas
check
diff -q out.txt "$QB_DIR/progs/files.out" >/dev/null || fail "files.bas with --allow: output differs"

# --for SECONDS: screensaver.bas stopped after 5 seconds of its virtual clock, normally, saying
# so; the picture is its screen then: the dots of the first frames (x = 13 is colour 14), not yet
# those of x = 200
run "$POINTCALC" --for 5 screensaver.bas -o saver.ppm
expect_rc 0 "--for 5"
expect_in err.txt "screensaver.bas:13: ran for 5 virtual seconds (--for): stopped" "--for: the note"
expect_eq "$(px320 saver.ppm 13 150)" "ffff55" "--for: the first frame's dot"
expect_eq "$(px320 saver.ppm 200 150)" "000000" "--for: no dot the program had not reached"
run "$POINTCALC" --for 0 screensaver.bas
expect_rc 2 "--for 0 is a usage error"

# --frames N --fps F of a QBasic program: frame k is the screen when its virtual clock reaches
# (k + 1) / F s; frames.bas moves its square 20 pixels per SLEEP 1.  After N frames the program
# is stopped, saying so; one that ends sooner holds its last screen for the frames still due
run "$POINTCALC" frames.bas --frames 4 --fps 1 -o fr.ppm -o fr.svg
expect_rc 0 "--frames 4 of a QBasic program"
expect_in err.txt "frames.bas:8: 4 frames taken (--frames): stopped" "--frames: the note where it stopped"
expect_eq "$(ls fr-*.ppm | tr '\n' ' ')" "fr-000.ppm fr-001.ppm fr-002.ppm fr-003.ppm " "--frames 4: four numbered frames"
expect_eq "$(px320 fr-000.ppm 20 55)" "ff5555" "frame 0: the square at x = 20"
expect_eq "$(px320 fr-000.ppm 40 55)" "000000" "frame 0: not yet at x = 40"
expect_eq "$(px320 fr-002.ppm 60 55)" "ff5555" "frame 2: the square at x = 60"
expect_eq "$(px320 fr-002.ppm 40 55)" "000000" "frame 2: erased at x = 40"
expect_eq "$(grep -c '<g visibility' fr.svg)" 4 "--frames: the animated SVG has 4 frames"
expect_in fr.svg 'x="80" y="50" width="10" height="10" fill="#ff5555"' "the SVG's last frame: the square at x = 80"
grep -q "x = 200" out.txt && fail "--frames 4: the program was stopped before its end"
run "$POINTCALC" frames.bas --frames 12 --fps 1 -o long.ppm
expect_rc 0 "--frames 12: more frames than the program makes"
expect_eq "$(ls long-*.ppm | wc -l | tr -d ' ')" 12 "--frames 12: twelve frames all the same"
expect_eq "$(px320 long-009.ppm 200 55)" "ff5555" "frame 9: the square's last place"
expect_eq "$(px320 long-011.ppm 200 55)" "ff5555" "frame 11: the last screen held"
expect_in out.txt "x = 200" "--frames 12: the program ran to its end"

# a program that never ends (a bouncing dot, by design) stopped by --timeout: the message names
# the program and the limit, without a Lua traceback, and the picture is still written
printf 'SCREEN 12\nCIRCLE (320, 240), 100, 14\nDO\n  x = (x + 1) MOD 640: PSET (x, 400), 10: PSET (x, 400), 0\nLOOP\n' >forever.bas
run "$POINTCALC" --timeout 1 forever.bas -o forever.ppm
expect_rc 1 "a program stopped by --timeout"
expect_eq "$(head -n 1 err.txt)" "forever.bas:4: time limit of 1 s exceeded: the program was stopped" \
    "--timeout: the message names the program's line"
expect_in err.txt "writing the screen as it stood" "--timeout: the note that the picture is written"
check
grep -q "traceback" err.txt && fail "--timeout: no Lua traceback"
expect_eq "$(ppm_pixel forever.ppm 420 240)" "ffff55" "--timeout: the picture written (the circle)"
# the line is the one running when the time came, inside a SUB too, and ON ERROR does not trap
# the limit (the first firing's message is kept: later ones come from the runtime's own code)
printf 'DECLARE SUB spin (n)\nSCREEN 13\nON ERROR GOTO 9\nspin 5\nEND\n9 PRINT "trapped": RESUME NEXT\nSUB spin (n)\n  DO\n    n = n + 1: PSET (n MOD 320, 100), 4\n  LOOP\nEND SUB\n' >insub.bas
run "$POINTCALC" --timeout 0.5 insub.bas -o insub.ppm
expect_rc 1 "a SUB stopped by --timeout"
expect_eq "$(head -n 1 err.txt)" "insub.bas:9: time limit of 0.5 s exceeded: the program was stopped" \
    "--timeout: the line inside the SUB"
grep -q "trapped" out.txt && fail "--timeout: ON ERROR does not trap the limit"
expect_eq "$(px320 insub.ppm 7 100)" "aa0000" "--timeout in a SUB: the picture written"
# Ctrl-C (SIGINT) stops a program as the time limit does: its line, and the picture written.  The
# signal is sent once the program has written ready.txt (so it is running, past its start)
printf 'SCREEN 12\nCIRCLE (320, 240), 100, 14\nOPEN "ready.txt" FOR OUTPUT AS #1: PRINT #1, "running": CLOSE #1\nDO\n  x = (x + 1) MOD 640: PSET (x, 400), 10: PSET (x, 400), 0\nLOOP\n' >ctrlc.bas
rm -f ready.txt
"$POINTCALC" ctrlc.bas -o ctrlc.ppm >out.txt 2>err.txt &
pid=$!
i=0
while [ ! -s ready.txt ] && [ $i -lt 600 ]; do sleep 0.05; i=$((i + 1)); done
kill -INT $pid
wait $pid
expect_eq "$?" 1 "Ctrl-C: exit status 1"
expect_eq "$(head -n 1 err.txt)" "ctrlc.bas:5: interrupted (Ctrl-C): the program was stopped" "Ctrl-C: the message names the line"
expect_in err.txt "writing the screen as it stood" "Ctrl-C: the note that the picture is written"
expect_eq "$(ppm_pixel ctrlc.ppm 420 240)" "ffff55" "Ctrl-C: the picture written (the circle)"

# --input FILE feeds INPUT and INKEY$ as standard input does (standard input itself is empty)
cp "$QB_DIR/progs/keyboard.bas" kb.bas
run "$POINTCALC" kb.bas --input "$QB_DIR/progs/keyboard.in" -o kb.ppm < /dev/null
expect_rc 0 "--input after the program"
check
diff -q out.txt "$QB_DIR/progs/keyboard.out" >/dev/null || fail "--input: output differs from keyboard.out"
run "$POINTCALC" --input "$QB_DIR/progs/keyboard.in" kb.bas -o kb.ppm < /dev/null
check
diff -q out.txt "$QB_DIR/progs/keyboard.out" >/dev/null || fail "--input before the program: output differs"
run "$POINTCALC" --input no-such-file kb.bas
expect_rc 2 "--input of a missing file"
expect_in err.txt "cannot open 'no-such-file'" "--input of a missing file: message"
run "$POINTCALC" --input kb.bas
expect_rc 2 "--input without a program"
# the programs in the styles found in the wild (wild_*.bas): the last frame of BALLPSET's
# kind of bouncing ball (SCREEN 13, PSET and PRESET) is a ring round (307, 180), erased
# elsewhere; SORTDEMO's bars (SCREEN 12), the longest last in colour 6; the VGA DAC entry 1
# written through the ports (63, 63, 0) colours the box
expect_eq "$(px320 wild_ballpset.ppm 312 180)" "ffff55" "wild_ballpset: the last ring"
expect_eq "$(px320 wild_ballpset.ppm 307 180)" "000000" "wild_ballpset: the ring's centre"
expect_eq "$(px320 wild_ballpset.ppm 160 100)" "000000" "wild_ballpset: the first ring erased"
expect_eq "$(ppm_pixel wild_sortdemo.ppm 5 224)" "aa5500" "wild_sortdemo: the last bar"
expect_eq "$(ppm_pixel wild_sortdemo.ppm 5 234)" "000000" "wild_sortdemo: below the bars"
expect_eq "$(px320 wild_poke.ppm 25 155)" "ffff00" "wild_poke: OUT &H3C9 recolours attribute 1"
expect_eq "$(px320 wild_poke.ppm 40 100)" "ff0000" "wild_poke: POKE colour 40 at row 100"
# The lowered blocks (a GOTO into a block, or every block of the module under ON ERROR GOTO)
# give the structured blocks' output: programs full of FOR, WHILE, DO, IF and SELECT run again
# with an error handler that is never used print the same
for name in control for_float32 operators print_format goto_into wild_gwgoto; do
    { echo "ON ERROR GOTO zzhandler"; cat "$QB_DIR/progs/$name.bas"; echo "END"; echo "zzhandler: RESUME NEXT"; } > "trap_$name.bas"
    run "$POINTCALC" "trap_$name.bas" -o "trap_$name.ppm" < /dev/null
    expect_rc 0 "trap_$name"
    check
    diff -u "$QB_DIR/progs/$name.out" out.txt >diff.txt || { fail "trap_$name: output differs from $name.out:"; cat diff.txt >&2; }
done
# REM $INCLUDE is not read, and the run names it with its line
expect_in wild_meta.err "wild_meta.bas:2: \$INCLUDE: 'qb.bi' not read" "\$INCLUDE named on standard error"
finish
