#!/bin/sh
# docs/api.md is generated from the help registry (interp/help.lua), the same text :help shows;
# this fails when the two disagree.  Regenerate with:
#   pointcalc docs/gen_api.lua > docs/api.md
. "$(dirname "$0")/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"

run "$POINTCALC" "$PC_SOURCE_DIR/docs/gen_api.lua"
expect_rc 0 "docs/gen_api.lua runs"
checks=$((checks + 1))
if ! cmp -s out.txt "$PC_SOURCE_DIR/docs/api.md"; then
    fail "docs/api.md is out of date with interp/help.lua; run 'pointcalc docs/gen_api.lua > docs/api.md':
$(diff "$PC_SOURCE_DIR/docs/api.md" out.txt | head -20)"
fi
expect_in out.txt '| `lerp` |' "the reference lists lerp"
expect_in out.txt '## REPL commands' "the reference lists the REPL commands"
finish
