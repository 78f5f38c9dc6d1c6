# Helpers for the QBasic tests, run by ctest with POINTCALC (the host binary), PC_SOURCE_DIR and
# PC_SHARED_DIR in the environment.  Each test works in a fresh temporary directory.
: "${POINTCALC:?POINTCALC must name the pointcalc binary}"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
QB_DIR="$PC_SOURCE_DIR/tests/qbasic"
failures=0
checks=0
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
check() { checks=$((checks + 1)); }

# run CMD...: status in $rc, stdout in out.txt, stderr in err.txt
run() { "$@" >out.txt 2>err.txt; rc=$?; }

expect_rc() {  # expect_rc WANT DESCRIPTION
    check
    [ "$rc" = "$1" ] || fail "$2: exit status $rc, want $1 (stderr: $(head -c 400 err.txt))"
}
expect_eq() { check; [ "$1" = "$2" ] || fail "$3: got '$1', want '$2'"; }
expect_in() {  # expect_in FILE TEXT DESCRIPTION
    check
    grep -qF -- "$2" "$1" || fail "$3: '$2' not in $1: $(head -c 400 "$1")"
}

# The RGB bytes of pixel (x, y) of a 640x480 PPM written by pointcalc (15-byte header).
ppm_pixel() { od -An -tx1 -j $((15 + ($3 * 640 + $2) * 3)) -N 3 "$1" | tr -d ' \n'; }
# How many bytes of the image are not 0 (black background): > 0 when something was drawn.
ppm_ink() { tail -c +16 "$1" | tr -d '\000' | wc -c | tr -d ' '; }

finish() {
    echo "$checks checks, $failures failed"
    [ "$failures" = 0 ]
}
