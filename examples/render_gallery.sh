#!/bin/sh
# Render every example script into a gallery: PNG and SVG per example and an index.html with a
# grid of thumbnails. Each figure shows its number and title (the script's first comment line),
# links its SVG, PNG and script, and where the script's opening comment cites a book section
# (Stepanov's "Example N", "Buimov §2.8.4 (Fig. 2.12)", ...) links that section in the page's
# list of sources. The scripts render in parallel, one per core (PC_JOBS overrides).
#   sh examples/render_gallery.sh POINTCALC OUTDIR
set -e
pc=$1
out=${2:-gallery}
: "${pc:?usage: sh render_gallery.sh POINTCALC [OUTDIR]}"
here=$(cd "$(dirname "$0")" && pwd)
case "$pc" in
    /*) ;;
    */*) pc="$(pwd)/$pc" ;;
    *) pc=$(command -v "$pc") || { echo "gallery: $1 not found" >&2; exit 2; } ;;
esac
jobs=${PC_JOBS:-$(nproc 2>/dev/null || echo 2)}
mkdir -p "$out"
out=$(cd "$out" && pwd)

# --- render: every script in its group's folder, in parallel; a failure leaves NAME.failed ---
for dir in "$here"/*/; do
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    mkdir -p "$out/$(basename "$dir")"
    for script in "$dir"*.lua; do printf '%s\n' "$script"; done
done | PC="$pc" OUT="$out" xargs -P "$jobs" -I{} sh -c '
    script=$1
    group=$(basename "$(dirname "$script")")
    name=$(basename "$script" .lua)
    cd "$OUT/$group"
    rm -f "$name.failed"
    cp "$script" "$name.lua"
    "$PC" "$script" -o "$name.png" -o "$name.svg" >/dev/null 2>"$name.err" || mv "$name.err" "$name.failed"
    # a script with a slider {animate = true} also plays: an animated SVG (docs/live.md)
    if [ ! -e "$name.failed" ] && grep -q "animate = true" "$script"; then
        "$PC" "$script" --frames 36 -o "$name-animated.svg" >/dev/null 2>"$name.err" || mv "$name.err" "$name.failed"
    fi
    rm -f "$name.err"' sh {}

# --- the book a figure reproduces, from the script's opening comment ---------------------
# Prints "ANCHOR<TAB>TEXT" (TEXT like "Stepanov 2013, §2, example 2") or nothing.
citation() {  # citation GROUP SCRIPT
    awk -v group="$1" '
    !/^--/ { exit }
    { sub(/^-- */, ""); head = head " " $0; if (NR == 1) first = $0 }
    function grab(re,   s) {   # the first match of re in the header, or ""
        return match(head, re) ? substr(head, RSTART, RLENGTH) : ""
    }
    END {
        if (group == "stepanov" && match(first, /^Example [0-9]+/)) {
            # the article: examples 1-8 in section 2, 9-13 in 3, 14-17 in 4, 18-25 in 5,
            # 26-31 in 6, 32-34 in 7
            n = substr(first, 9, RLENGTH - 8) + 0
            s = n <= 8 ? 2 : n <= 13 ? 3 : n <= 17 ? 4 : n <= 25 ? 5 : n <= 31 ? 6 : 7
            printf "src-stepanov-%d\tStepanov 2013, §%d, example %d\n", s, s, n
            exit
        }
        # the work: its author as the header names it; the year given there, or else that of the work
        who = grab("(Korotky & Vitovtov|Buimov|Konopatsky|Korotky|Stepanov)")
        if (who == "" && group ~ /^(buimov|konopatsky|korotky)$/)
            who = toupper(substr(group, 1, 1)) substr(group, 2)
        if (who == "") exit
        year = ""
        if (match(head, who " \\([0-9][0-9][0-9][0-9]\\)")) year = substr(head, RSTART + RLENGTH - 5, 4)
        if (year == "") year = who == "Stepanov" ? 2013 : who == "Buimov" ? 2012 : \
                               who == "Konopatsky" ? 2025 : who == "Korotky" ? 2015 : 2021
        key = tolower(who); sub(/ .*/, "", key)
        if (key == "korotky") key = key "-" year
        text = who " " year
        # its section or chapter, then the first example or figure named
        sec = grab("(§ ?|ch\\. )[0-9]+(\\.[0-9]+)*")
        if (sec != "") text = text ", " sec
        ex = grab("[Ee]xample [0-9]+(\\.[0-9]+)*"); exat = RSTART
        num = "[0-9]+[a-z]?(\\.[0-9]+[a-z]?)*"   # 2.12, 3a; ranges 5.1-5.3 and lists 1, 4a
        num = num "((-|–)" num ")?"
        fig = grab("(Figs?\\.?|Figure) " num "(, " num ")*")
        figat = RSTART
        if (fig != "") { plural = fig ~ /^Figs/; sub(/^[A-Za-z]+\.? /, "", fig); fig = (plural ? "Figs. " : "Fig. ") fig }
        if (ex != "") ex = "example " substr(ex, 9)
        if (ex != "" && (fig == "" || exat < figat)) text = text ", " ex
        else if (fig != "") text = text ", " fig
        printf "src-%s\t%s\n", key, text
    }' "$2"
}

html_text() { sed 's/&/\&amp;/g; s/</\&lt;/g; s/>/\&gt;/g'; }

# --- the page ------------------------------------------------------------------------------
index="$out/index.html.tmp"
cat > "$index" <<'HTML'
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pointcalc gallery</title>
<style>
body { font-family: sans-serif; background: #222; color: #eee; margin: 2em; }
h2 { border-bottom: 1px solid #555; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(260px, 1fr)); gap: 1em; }
figure { margin: 0; background: #111; padding: .5em; border-radius: 4px; }
figure img { width: 100%; height: auto; display: block; }
figcaption { font-size: .9em; margin-top: .3em; }
.source { color: #bbb; }
a { color: #9cf; }
dd { margin-bottom: .6em; }
dt { font-weight: bold; }
li:target, dt:target { background: #445; }
</style></head><body>
<h1>pointcalc gallery</h1>
HTML
failed=0
count=0
for dir in "$here"/*/; do
    group=$(basename "$dir")
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    printf '<h2 id="%s">%s</h2>\n<div class="grid">\n' "$group" "$group" >> "$index"
    for script in "$dir"*.lua; do
        name=$(basename "$script" .lua)
        if [ -e "$out/$group/$name.failed" ]; then
            echo "gallery: $group/$name failed:" >&2
            sed 's/^/  /' "$out/$group/$name.failed" | head -5 >&2
            failed=$((failed + 1))
            continue
        fi
        count=$((count + 1))
        title=$(sed -n '1s/^-- *//p' "$script" | html_text)
        cite=$(citation "$group" "$script")
        source=
        if [ -n "$cite" ]; then
            source=$(printf '<br><span class="source">after <a href="#%s">%s</a></span>' \
                "${cite%%	*}" "$(printf '%s' "${cite#*	}" | html_text)")
        fi
        f="$group/$name"
        live=
        if [ -e "$out/$f-animated.svg" ]; then
            live=$(printf '<br><span class="live"><a href="%s-animated.svg">animation</a> · live: <code>pointcalc serve %s.lua</code> (docs/live.md)</span>' "$f" "$name")
        fi
        printf '<figure id="%s-%s"><a href="%s.svg"><img src="%s.png" alt="%s" width="640" height="480" loading="lazy"></a>\n<figcaption>%s%s%s<br><a href="%s.svg">SVG</a> · <a href="%s.png">PNG</a> · <a href="%s.lua">script</a></figcaption></figure>\n' \
            "$group" "$name" "$f" "$f" "$name" "$title" "$source" "$live" "$f" "$f" "$f" >> "$index"
    done
    echo '</div>' >> "$index"
done
cat >> "$index" <<'HTML'
<h2 id="sources">Sources</h2>
<dl>
<dt id="src-stepanov">Stepanov 2013</dt>
<dd>M. E. Stepanov, “The method of curvilinear coordinates in computer geometry” (Метод криволинейных
координат в компьютерной геометрии), <i>Modelling and Data Analysis</i> (Моделирование и анализ
данных), 2013, vol. 3, no. 1, pp. 157–192. Thirty-four numbered examples with QBasic listings:
<ul>
<li id="src-stepanov-2">§2, kinematic construction of curves in Cartesian coordinates: examples 1–8</li>
<li id="src-stepanov-3">§3, images built with the kinematic method: examples 9–13</li>
<li id="src-stepanov-4">§4, lines in curvilinear coordinates: examples 14–17</li>
<li id="src-stepanov-5">§5, curvilinear coordinate systems with given properties: examples 18–25</li>
<li id="src-stepanov-6">§6, mathematical questions: examples 26–31</li>
<li id="src-stepanov-7">§7, three-dimensional space: examples 32–34</li>
</ul></dd>
<dt id="src-buimov">Buimov 2012</dt>
<dd>B. A. Buimov, <i>Computer geometry and graphics</i> (Компьютерная геометрия и графика), TUSUR,
Tomsk, 2012: transformations, projections, curves and surfaces.</dd>
<dt id="src-konopatsky">Konopatsky 2025</dt>
<dd>E. V. Konopatsky, <i>Modelling geometric objects in point calculus. Part 1. Curves</i>
(Моделирование геометрических объектов в точечном исчислении. Часть 1. Кривые), NNGASU, 2025.</dd>
<dt id="src-korotky-2021">Korotky &amp; Vitovtov 2021</dt>
<dd>V. A. Korotky, I. G. Vitovtov, “Modelling nature-like curves” (Моделирование природоподобных
кривых), <i>Vestnik BGTU</i>, 2021, no. 6, pp. 11–22,
<a href="https://doi.org/10.30987/1999-8775-2021-6-11-22">doi:10.30987/1999-8775-2021-6-11-22</a>.</dd>
<dt id="src-korotky-2015">Korotky 2015</dt>
<dd>V. A. Korotky, “Second-order curves in surface modelling” (Кривые второго порядка в моделировании
поверхностей), online conference paper, 2015.</dd>
</dl>
</body></html>
HTML
mv "$index" "$out/index.html"
echo "gallery: $count examples rendered into $out (open index.html)"
[ "$failed" = 0 ]
