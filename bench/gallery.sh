#!/bin/sh
# Wall-clock time to render the whole gallery (every example to PNG and SVG, and the index),
# as the README's first command does after building.  sh bench/gallery.sh POINTCALC
pc=${1:-build/pointcalc}
out=$(mktemp -d)
start=$(date +%s.%N)
sh examples/render_gallery.sh "$pc" "$out" >/dev/null || exit 1
end=$(date +%s.%N)
n=$(ls "$out"/*/*.png | wc -l)
echo "gallery: $n figures rendered to PNG and SVG in $(awk "BEGIN { printf \"%.2f\", $end - $start }") s (wall clock)"
rm -rf "$out"
