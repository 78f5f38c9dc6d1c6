#!/bin/sh
# Render every example script into a gallery: PNG and SVG per example and an index.html with
# a grid of thumbnails (number and title from the script's first comment line).
#   sh examples/render_gallery.sh POINTCALC OUTDIR
set -e
pc=$1
out=${2:-gallery}
here=$(cd "$(dirname "$0")" && pwd)
case "$pc" in /*) ;; *) pc="$(pwd)/$pc" ;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)
index="$out/index.html.tmp"
cat > "$index" <<'HTML'
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pointcalc gallery</title>
<style>
body { font-family: sans-serif; background: #222; color: #eee; margin: 2em; }
h2 { border-bottom: 1px solid #555; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(260px, 1fr)); gap: 1em; }
figure { margin: 0; background: #111; padding: .5em; border-radius: 4px; }
figure img { width: 100%; image-rendering: auto; }
figcaption { font-size: .9em; margin-top: .3em; }
a { color: #9cf; }
</style></head><body>
<h1>pointcalc gallery</h1>
HTML
failed=0
count=0
for dir in "$here"/*/; do
    group=$(basename "$dir")
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    printf '<h2>%s</h2>\n<div class="grid">\n' "$group" >> "$index"
    mkdir -p "$out/$group"
    for script in "$dir"*.lua; do
        name=$(basename "$script" .lua)
        title=$(sed -n '1s/^-- *//p' "$script" | sed 's/&/\&amp;/g; s/</\&lt;/g')
        if (cd "$out/$group" && "$pc" "$script" -o "$name.png" -o "$name.svg" >/dev/null); then
            count=$((count + 1))
            cp "$script" "$out/$group/$name.lua"
            printf '<figure><a href="%s/%s.svg"><img src="%s/%s.png" alt="%s" loading="lazy"></a>\n<figcaption>%s<br><a href="%s/%s.svg">SVG</a> · <a href="%s/%s.png">PNG</a> · <a href="%s/%s.lua">script</a></figcaption></figure>\n' \
                "$group" "$name" "$group" "$name" "$name" "$title" "$group" "$name" "$group" "$name" "$group" "$name" >> "$index"
        else
            echo "gallery: $group/$name failed" >&2
            failed=$((failed + 1))
        fi
    done
    echo '</div>' >> "$index"
done
echo '</body></html>' >> "$index"
mv "$index" "$out/index.html"
echo "gallery: $count examples rendered into $out (open index.html)"
[ "$failed" = 0 ]
