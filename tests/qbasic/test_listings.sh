# Every cleaned listing of ../shared/listings/stepanov runs as it is and draws something.
# The listings are test inputs read in place: they are not part of this repository.
. "$(dirname "$0")/lib.sh"

LISTINGS="${PC_SHARED_DIR:-}/listings/stepanov"
if [ ! -d "$LISTINGS" ]; then
    echo "SKIP: $LISTINGS is absent (the Stepanov listings are not available here)"
    exit 0
fi
n=0
for bas in "$LISTINGS"/*.bas; do
    name=$(basename "$bas" .bas)
    run "$POINTCALC" "$bas" -o "$name.ppm"
    expect_rc 0 "$name"
    expect_eq "$(head -c 2 err.txt)" "" "$name: nothing on standard error"
    check
    [ -s "$name.ppm" ] && [ "$(ppm_ink "$name.ppm")" -gt 0 ] || fail "$name: drew nothing"
    n=$((n + 1))
done
expect_eq "$([ "$n" -ge 34 ] && echo yes)" yes "all listings found ($n)"

# a few facts of the pictures (stepanov_examples.md §C): Example 1's rectangle corner (200, 100)
# and the ellipse's leftmost point (200, 250) are white; Example 3's box is filled cyan;
# Example 8's frame is drawn in colour 0 and stays invisible
expect_eq "$(ppm_pixel ex01.ppm 200 100)" "ffffff" "ex01 rectangle corner"
expect_eq "$(ppm_pixel ex01.ppm 250 250)" "000000" "ex01 inside the ellipse"
expect_eq "$(ppm_pixel ex03.ppm 290 390)" "00aaaa" "ex03 filled cyan box"
expect_eq "$(ppm_pixel ex08.ppm 120 300)" "000000" "ex08 colour-0 frame invisible"
finish
