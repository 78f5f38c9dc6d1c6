# The fuzzers of tests/fuzz in the test run (issue 15): a seeded random-call fuzzer over every
# function and method of the help registry, and a mutational fuzzer over the QBasic corpus
# (tests/qbasic/progs).  Fixed seeds, a bounded number of cases: the same run every time, well
# within a minute under AddressSanitizer.  Crashes (the process dies) and messages without the
# caller's line must be 0.  Longer runs and the libFuzzer targets: docs/safety.md.
. "$(dirname "$0")/lib.sh"
FUZZ="$PC_SOURCE_DIR/tests/fuzz"

for seed in 1 2 3; do
    "$POINTCALC" --timeout 120 "$FUZZ/api_fuzz.lua" $seed 8000 api$seed.log </dev/null >out.txt 2>err.txt; rc=$?
    expect_rc 0 "api_fuzz seed $seed (crash or unlocated messages; last case: $(tail -n 1 api$seed.log))"
    expect_in out.txt "8000 cases" "api_fuzz seed $seed ran to the end"
    expect_in out.txt " 0 unlocated" "api_fuzz seed $seed: messages without a location"
    tail -n 1 out.txt
done

for seed in 1 2; do
    "$POINTCALC" --timeout 120 "$FUZZ/bas_fuzz.lua" $seed 1500 "$PC_SOURCE_DIR"/tests/qbasic/progs/*.bas \
        --log bas$seed.log </dev/null >out.txt 2>err.txt; rc=$?
    expect_rc 0 "bas_fuzz seed $seed (crash or defects: $(head -c 600 err.txt))"
    expect_in out.txt "defects: 0 unlocated, 0 internal, 0 invalid Lua" "bas_fuzz seed $seed"
    # the mutants must reach every stage, or the fuzzer tests nothing
    expect_eq "$(grep -c ' 0 refused\| 0 ran,\| 0 QBasic errors' out.txt)" "0" "bas_fuzz seed $seed reaches every stage"
    tail -n 1 out.txt
done

finish
