# The project's own QBasic programs (tests/qbasic/progs/*.bas): each must run without error and
# PRINT exactly its .out file.  They cover PRINT formatting, the float32 FOR loop counts, the RND
# sequence, operators and their precedence, variables and types, control flow (IF, GOTO, WHILE,
# DO, EXIT, SELECT CASE), DATA/READ/RESTORE, SUB/FUNCTION/DEF FN/GOSUB, strings, and the drawing
# statements (through POINT).
. "$(dirname "$0")/lib.sh"

n=0
for bas in "$QB_DIR"/progs/*.bas; do
    name=$(basename "$bas" .bas)
    cp "$bas" "$name.bas"
    run "$POINTCALC" "$name.bas" -o "$name.ppm"
    expect_rc 0 "$name"
    check
    if ! diff -u "$QB_DIR/progs/$name.out" out.txt >diff.txt; then
        fail "$name: output differs from $name.out:"
        cat diff.txt >&2
    fi
    n=$((n + 1))
done
expect_eq "$([ "$n" -ge 10 ] && echo yes)" yes "at least 10 programs found in $QB_DIR/progs"

# the same pictures through the writers: graphics.bas drew pixel (10, 10) in red 4, (20, 21) in
# white, (75, 55) inside a BF box in magenta 5, and the painted disc (200, 200) in blue 1
expect_eq "$(ppm_pixel graphics.ppm 10 10)" "aa0000" "PPM pixel (10,10) = colour 4"
expect_eq "$(ppm_pixel graphics.ppm 20 21)" "ffffff" "PPM pixel (20,21) = colour 15"
expect_eq "$(ppm_pixel graphics.ppm 75 55)" "aa00aa" "PPM pixel (75,55) = colour 5"
expect_eq "$(ppm_pixel graphics.ppm 200 200)" "0000aa" "PPM pixel (200,200) = colour 1"
expect_eq "$(ppm_pixel graphics.ppm 11 10)" "000000" "PPM pixel (11,10) = background"
# graphics2.bas redefined attribute 1 as PALETTE 1, 63 + 256 * 32 (6-bit red 63, green 32)
expect_eq "$(ppm_pixel graphics2.ppm 5 5)" "ff8200" "PALETTE reaches the written picture"
finish
