#!/bin/sh
# Wall-clock time to render the whole gallery (every example of every folder to PNG and SVG, and
# the index), as `./build.sh gallery` does after building: on all cores, then on one for the
# ratio.  sh bench/gallery.sh [POINTCALC]
pc=${1:-build/pointcalc}
cores=$(nproc 2>/dev/null || echo 2)

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
render() {  # render JOBS: renders into $out/JOBS and prints the wall time in seconds
    start=$(date +%s.%N)
    PC_JOBS=$1 PC_GALLERY_PDF=0 sh examples/render_gallery.sh "$pc" "$out/$1" >/dev/null || exit 1
    end=$(date +%s.%N)
    awk "BEGIN { printf \"%.2f\", $end - $start }"
}

parallel=$(render "$cores") || exit 1
serial=$(render 1) || exit 1
counts=$(for d in "$out/$cores"/*/; do printf '%s %s, ' "$(ls "$d"*.png | wc -l)" "$(basename "$d")"; done)
n=$(ls "$out/$cores"/*/*.png | wc -l)
echo "gallery: $n figures (${counts%, }) rendered to PNG and SVG in $parallel s on $cores cores, $serial s on one (wall clock)"
