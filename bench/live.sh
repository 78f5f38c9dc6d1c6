#!/bin/sh
# Latency of the live page over the Stepanov gallery: slider change to new SVG, median and
# worst (bench/live.py).  sh bench/live.sh POINTCALC
pc=${1:-build/pointcalc}
exec python3 "$(dirname "$0")/live.py" "$pc" "$(dirname "$0")"/../examples/stepanov/*.lua --renders 5
