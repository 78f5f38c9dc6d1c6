# Helpers for the command-line tests: run from ctest with POINTCALC set to the host binary.
: "${POINTCALC:?POINTCALC must name the pointcalc binary}"
failures=0
checks=0
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# run CMD...: runs it, keeping status in $rc, stdout in out.txt, stderr in err.txt
run() { "$@" >out.txt 2>err.txt; rc=$?; }

expect_rc() {  # expect_rc WANT DESCRIPTION
    checks=$((checks + 1))
    [ "$rc" = "$1" ] || fail "$2: exit status $rc, want $1 (stderr: $(head -c 400 err.txt))"
}
expect_in() {  # expect_in FILE TEXT DESCRIPTION
    checks=$((checks + 1))
    grep -qF -- "$2" "$1" || fail "$3: '$2' not in $1: $(head -c 400 "$1")"
}
expect_file() { checks=$((checks + 1)); [ -s "$1" ] || fail "$2: $1 missing or empty"; }
expect_no_file() { checks=$((checks + 1)); [ ! -e "$1" ] || fail "$2: $1 should not exist"; }
expect_eq() { checks=$((checks + 1)); [ "$1" = "$2" ] || fail "$3: got '$1', want '$2'"; }

finish() {
    echo "$checks checks, $failures failed"
    [ "$failures" = 0 ]
}
