#!/bin/sh
# The REPL through a pseudo-terminal: values, multi-line chunks, errors, Tab completion, :help,
# :show, :save, :load, :clear, :quit, history in $HOME, colour, --watch, -i.  The driver is
# tests/cli/repl_pty.py (python3's pty module); it runs in lib.sh's scratch folder.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"

# --watch on the command line: a usage error for a file it cannot write
run "$POINTCALC" --watch pic.gif; expect_rc 2 "--watch with an unknown extension"
expect_in err.txt "cannot watch 'pic.gif': the extension must be .png, .svg or .ppm" "--watch message"
run "$POINTCALC" --watch;         expect_rc 2 "--watch without a file"

# :show counts as empty the colour the screen was cleared to, not COLOR's background before
# the CLS that applies it: one dot at (5, 5) is the single dot of the first cell (U+2801)
printf 'color(15, 1)\npset(5, 5)\n:show 20\n' | "$POINTCALC" -i >out.txt 2>err.txt
expect_eq "$(grep -o '⠁' out.txt | wc -l) $(grep -c '⣿' out.txt)" "1 0" ":show after color(fg, bg) before cls"
printf 'color(15, 1)\ncls()\npset(5, 5)\n:show 20\n' | "$POINTCALC" -i >out.txt 2>err.txt
expect_eq "$(grep -o '⠁' out.txt | wc -l) $(grep -c '⣿' out.txt)" "1 0" ":show after cls in colour 1"

# the REPL itself, typed at through a pseudo-terminal
checks=$((checks + 1))
python3 "$here/repl_pty.py" || fail "the REPL session (see the FAIL lines above)"
finish
