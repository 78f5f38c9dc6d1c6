# Errors as QBasic names them, with the program's line: every tests/qbasic/errors/*.bas starts
# with "' EXPECT: LINE: MESSAGE"; running it must fail (exit status 1) with the first line of
# standard error exactly "NAME.bas:LINE: MESSAGE".  Translation errors (Syntax error, NEXT
# without FOR, ...) and runtime errors (Out of DATA, Division by zero, ...) alike.
. "$(dirname "$0")/lib.sh"

n=0
for bas in "$QB_DIR"/errors/*.bas; do
    name=$(basename "$bas")
    want="$name:$(head -n 1 "$bas" | sed "s/^' EXPECT: //")"
    cp "$bas" "$name"
    run "$POINTCALC" "$name"
    expect_rc 1 "$name"
    expect_eq "$(head -n 1 err.txt)" "$want" "$name: error message"
    n=$((n + 1))
done
expect_eq "$([ "$n" -ge 20 ] && echo yes)" yes "at least 20 error programs found"

# --emit-lua reports translation errors the same way, and nothing on standard output
cp "$QB_DIR/errors/next_without_for.bas" nwf.bas
run "$POINTCALC" --emit-lua nwf.bas
expect_rc 1 "--emit-lua of a bad program"
expect_eq "$(head -n 1 err.txt)" "nwf.bas:3: NEXT without FOR" "--emit-lua error message"
expect_eq "$(wc -c < out.txt | tr -d ' ')" 0 "--emit-lua prints nothing on error"
# a runtime error is the QBasic message alone; the Lua traceback only on request
cp "$QB_DIR/errors/out_of_data.bas" ood.bas
run "$POINTCALC" ood.bas
expect_eq "$(cat err.txt)" "ood.bas:4: Out of DATA" "runtime error without a traceback"
PC_QBASIC_TRACEBACK=1 run "$POINTCALC" ood.bas
expect_in err.txt "stack traceback:" "runtime error traceback with PC_QBASIC_TRACEBACK=1"
# a refused SCREEN mode: nothing ran
cp "$QB_DIR/errors/screen_mode.bas" sm.bas
run "$POINTCALC" sm.bas
expect_eq "$(wc -c < out.txt | tr -d ' ')" 0 "an unsupported SCREEN mode is refused before the program runs"
finish
