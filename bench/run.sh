#!/bin/sh
# Run every benchmark: sh bench/run.sh POINTCALC.  Benchmarks are never part of the tests.
pc=${1:-build/pointcalc}
cd "$(dirname "$0")/.." || exit 1
for b in bench/*.lua; do
    echo "== $b"
    "$pc" "$b" || exit 1
done
for b in bench/*.sh; do
    [ "$b" = bench/run.sh ] && continue
    echo "== $b"
    sh "$b" "$pc" || exit 1
done
