# The argument layer at the command line (docs/bindings.md): a misspelt global in a script and
# in a -e chunk gets the registry's suggestion, and a declared function's message names the
# user's call and line.
. "$(dirname "$0")/lib.sh"

printf 'local c = korotky.elastic({P(0, 0), P(1, 1), P(2, 0)})\nlable(c, "x")\n' > misspelt.lua
run "$POINTCALC" misspelt.lua
expect_rc 1 "a misspelt global fails the script"
expect_in err.txt "misspelt.lua:2: attempt to call a nil value (global 'lable') (did you mean 'label'?)" "script: did you mean"

run "$POINTCALC" -e 'local M = lerpp.x'
expect_rc 1 "a misspelt global in -e"
expect_in err.txt "(command line):1: attempt to index a nil value (global 'lerpp') (did you mean 'lerp'?)" "-e: indexing a nil global"

run "$POINTCALC" -e 'zzqqxx()'
expect_rc 1 "a name near nothing"
expect_in err.txt "attempt to call a nil value (global 'zzqqxx')" "no suggestion for a name near nothing"
checks=$((checks + 1)); grep -q "did you mean" err.txt && fail "zzqqxx: suggested $(cat err.txt)"

printf 'local pts = {P(0, 0), P(1, 1), P(2, 0)}\nbuimov.spline(pts, {edns = "cyclic"})\n' > key.lua
run "$POINTCALC" key.lua
expect_rc 1 "a misspelt option key"
expect_in err.txt "key.lua:2: buimov.spline: unknown option 'edns' (did you mean 'ends'?)" "option key suggestion at the user's line"

finish
