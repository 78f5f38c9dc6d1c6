#!/bin/sh
# The argument layer's per-call cost against hand-written lua_tonumber bindings in one run
# (bench/args_c.c; built on demand: cmake --build build --target args_c).
#   sh bench/args.sh [POINTCALC]
pc=${1:-build/pointcalc}
dir=$(dirname "$pc")
cmake --build "$dir" --target args_c >/dev/null || exit 1
"$dir/args_c" 1000000 15
