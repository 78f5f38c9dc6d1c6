#!/bin/sh
# The REPL through a pseudo-terminal: values, multi-line chunks, errors, Tab completion, :help,
# :show, :save, :load, :clear, :quit, history in $HOME, colour, --watch, -i.  The driver is
# tests/cli/repl_pty.py (python3's pty module); it runs in lib.sh's scratch folder.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
POINTCALC=$(command -v "$POINTCALC" || echo "$POINTCALC") python3 "$here/repl_pty.py"
