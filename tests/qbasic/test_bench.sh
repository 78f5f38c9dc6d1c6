# bench/qbasic.lua runs (a translated QBasic loop against the same loop in Lua) and reports its
# ratios; a small N keeps it quick.  The figure itself is docs/qbasic.md's.
. "$(dirname "$0")/lib.sh"

run "$POINTCALC" "$PC_SOURCE_DIR/bench/qbasic.lua" 3000
expect_rc 0 "bench/qbasic.lua"
expect_in out.txt "QBasic loop of 3000 points" "bench: the loop ran"
check
grep -Eq "^translated QBasic: +[0-9]+\.[0-9]+ x baseline$" out.txt || fail "bench: no ratio for the translated program: $(cat out.txt)"
expect_eq "$(wc -c < err.txt | tr -d ' ')" 0 "bench: nothing on standard error"
finish
