#!/bin/sh
# Render every example script into a gallery: PNG and SVG per example and an index.html with a
# grid of thumbnails. Each figure shows its number and title (the script's first comment line),
# links its SVG, PNG and script, and where the script's opening comment cites a book section
# (Stepanov's "Example N", "Buimov §2.8.4 (Fig. 2.12)", ...) links that section in the page's
# list of sources. The scripts render in parallel, one per core (PC_JOBS overrides). The page
# has contents by book and chapter, a filter, a page per figure, and where the program writes
# PDF a PDF atlas per book (gallery_atlas.sh).
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

# The print look: where the program writes PDF (the print renderer), each figure also goes to
# PDF and each book gets an atlas of its figures, captioned with their numbers and titles
# (PC_GALLERY_PDF=0 leaves them out)
pdf=
if [ "${PC_GALLERY_PDF:-1}" != 0 ] && "$pc" -e 'pset(0, 0)' -o "$out/.probe.pdf" >/dev/null 2>&1 &&
   [ -s "$out/.probe.pdf" ] && command -v gs >/dev/null; then
    pdf=1
fi
rm -f "$out/.probe.pdf"

# --- render: every script in its group's folder, in parallel; a failure leaves NAME.failed ---
for dir in "$here"/*/; do
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    mkdir -p "$out/$(basename "$dir")"
    for script in "$dir"*.lua; do printf '%s\n' "$script"; done
done | PC="$pc" OUT="$out" PDF="$pdf" xargs -P "$jobs" -I{} sh -c '
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
    # the print look for the atlas of its book (a failure only leaves the figure out of it)
    if [ -n "$PDF" ] && [ ! -e "$name.failed" ]; then
        "$PC" "$script" -o "$name.pdf" >/dev/null 2>&1 || rm -f "$name.pdf"
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

html_attr() { html_text | sed 's/"/\&quot;/g' | tr '\n' ' '; }

# What the page's filter searches for a script: its opening comment (title, book, figure and
# example numbers) and the functions it calls
search_text() {  # search_text SCRIPT
    { sed -n '/^--/!q; s/^-- *//p' "$1"
      grep -o '[A-Za-z_][A-Za-z0-9_.:]*[[:space:]]*[({"]' "$1" | sed 's/[[:space:]({"]*$//' | sort -u
    } | tr 'A-Z' 'a-z' | html_attr
}
# The chapter of a citation, for the contents: the article's sections ("Stepanov 2013, §2, ...")
# and the books' chapters ("Buimov 2012, §2.8.4, Fig. 2.12" -> "ch. 2", "Fig. 4.5" -> "ch. 4")
chapter() {  # chapter GROUP CITATION
    n=$(printf '%s\n' "$2" | sed -n 's/.*§ *\([0-9][0-9]*\).*/\1/p; t; s/.*ch\. *\([0-9][0-9]*\).*/\1/p; t; s/.*Figs*\. *\([0-9][0-9]*\)\..*/\1/p')
    [ -z "$n" ] && return
    if [ "$1" = stepanov ]; then echo "§$n"; else echo "ch. $n"; fi
}


# --- the page ------------------------------------------------------------------------------
index="$out/index.html.tmp"
body="$out/body.html.tmp"
contents="$out/contents.html.tmp"
: > "$body"
: > "$contents"
cat > "$index" <<'HTML'
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pointcalc gallery</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<style>
body { font-family: sans-serif; background: #222; color: #eee; margin: 0 2em 2em; }
h2 { border-bottom: 1px solid #555; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(360px, 1fr)); gap: 1em; }
figure { margin: 0; background: #111; padding: .5em; border-radius: 4px; }
figure img { width: 100%; height: auto; display: block; cursor: zoom-in; }
figcaption { font-size: .9em; margin-top: .3em; }
.source { color: #bbb; }
a { color: #9cf; }
dd { margin-bottom: .6em; }
dt { font-weight: bold; }
li:target, dt:target, figure:target { background: #445; }
#bar { position: sticky; top: 0; background: #222; padding: .6em 0; z-index: 1; display: flex;
       gap: 1em; align-items: center; flex-wrap: wrap; border-bottom: 1px solid #444; }
#bar h1 { font-size: 1.3em; margin: 0; }
#filter { font: inherit; padding: .2em .4em; min-width: 22em; background: #111; color: #eee;
          border: 1px solid #666; }
#contents { columns: 4 14em; font-size: .9em; margin: 1em 0; }
#contents > li { break-inside: avoid; margin-bottom: .5em; }
#contents ul { padding-left: 1.2em; margin: .2em 0; }
[hidden] { display: none !important; }
#viewer { position: fixed; inset: 0; background: rgba(0, 0, 0, .92); display: flex;
          align-items: center; justify-content: center; z-index: 2; cursor: zoom-out; }
#viewer img { max-width: 96vw; max-height: 92vh; width: 96vw; height: auto; object-fit: contain; }
#viewer p { position: absolute; bottom: .5em; left: 0; right: 0; text-align: center; }
</style></head><body>
<div id="bar"><h1>pointcalc gallery</h1>
<input id="filter" type="search" placeholder="filter: fig. 2.12, example 27, oval, lerp"
       aria-label="filter the figures">
<span id="shown"></span></div>
HTML
failed=0
count=0
for dir in "$here"/*/; do
    group=$(basename "$dir")
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    printf '<section id="%s" class="book"><h2>%s</h2>\n<div class="grid">\n' "$group" "$group" >> "$body"
    chapters=
    gcount=0
    set -- "$dir"*.lua
    for script in "$@"; do
        name=$(basename "$script" .lua)
        if [ -e "$out/$group/$name.failed" ]; then
            echo "gallery: $group/$name failed:" >&2
            sed 's/^/  /' "$out/$group/$name.failed" | head -5 >&2
            failed=$((failed + 1))
            continue
        fi
        count=$((count + 1))
        gcount=$((gcount + 1))
        title=$(sed -n '1s/^-- *//p' "$script" | html_text)
        cite=$(citation "$group" "$script")
        source=
        citetext=
        if [ -n "$cite" ]; then
            citetext=$(printf '%s' "${cite#*	}" | html_text)
            source=$(printf '<br><span class="source">after <a href="#%s">%s</a></span>' \
                "${cite%%	*}" "$citetext")
            # the contents: a book's chapters, each linking its first figure
            ch=$(chapter "$group" "${cite#*	}")
            if [ -n "$ch" ] && ! printf '%s\n' "$chapters" | grep -qxF "$ch"; then
                chapters=$(printf '%s\n%s' "$chapters" "$ch")
                printf '<li><a href="#%s-%s">%s</a></li>\n' "$group" "$name" "$ch" >> "$contents.$group"
            fi
        fi
        f="$group/$name"
        live=
        if [ -e "$out/$f-animated.svg" ]; then
            live=$(printf '<br><span class="live"><a href="%s-animated.svg">animation</a> · live: <code>pointcalc serve %s.lua</code> (docs/live.md)</span>' "$f" "$name")
        fi
        printf '<figure id="%s-%s" data-search="%s %s %s"><a href="%s.svg" class="zoom"><img src="%s.png" alt="%s" width="640" height="480" loading="lazy"></a>\n<figcaption>%s%s%s<br><a href="%s.html">page</a> · <a href="%s.svg">SVG</a> · <a href="%s.png">PNG</a> · <a href="%s.lua">script</a></figcaption></figure>\n' \
            "$group" "$name" "$name" "$(printf '%s' "$citetext" | tr 'A-Z' 'a-z')" "$(search_text "$script")" \
            "$f" "$f" "$name" "$title" "$source" "$live" "$f" "$f" "$f" "$f" >> "$body"
        # the figure's own page: the figure, its citation and its script
        {
            printf '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>%s — pointcalc gallery</title>\n' "$title"
            printf '<style>body { font-family: sans-serif; background: #222; color: #eee; margin: 1em 2em; } a { color: #9cf; }\nimg { width: 100%%; max-width: 1280px; height: auto; display: block; }\npre { background: #111; padding: .8em; overflow: auto; }</style></head><body>\n'
            printf '<p><a href="../index.html#%s-%s">gallery</a> · %s</p>\n<h1>%s</h1>\n' "$group" "$name" "$group" "$title"
            [ -n "$citetext" ] && printf '<p class="source">After <a href="../index.html#%s">%s</a>.</p>\n' "${cite%%	*}" "$citetext"
            printf '<p><img src="%s.svg" alt="%s"></p>\n<p><a href="%s.svg">SVG</a> · <a href="%s.png">PNG</a> · <a href="%s.lua">script</a>' "$name" "$name" "$name" "$name" "$name"
            [ -n "$pdf" ] && printf ' · <a href="%s.pdf">PDF</a>' "$name"
            printf '</p>\n<h2>The script</h2>\n<pre><code>'
            html_text < "$script"
            printf '</code></pre>\n<p>Run it: <code>pointcalc %s.lua -o %s.png</code></p>\n</body></html>\n' "$name" "$name"
        } > "$out/$f.html"
        # the print look, and its caption in the atlas
        if [ -n "$pdf" ]; then
            caption=$(printf '%s' "${cite#*	}" | sed 's/^[^,]*, //')
            [ -n "$caption" ] && caption="$caption: "
            printf '%s\t%s%s\n' "$f.pdf" "$caption" "$(sed -n '1s/^-- *//p' "$script")" >> "$out/$group/atlas.list"
        fi
    done
    echo '</div></section>' >> "$body"
    atlas=
    if [ -n "$pdf" ] && [ -s "$out/$group/atlas.list" ]; then
        sh "$here/gallery_atlas.sh" "$out" "$group" "$out/$group/atlas.list" && atlas=1
        rm -f "$out/$group/atlas.list"
    fi
    {
        printf '<li><a href="#%s">%s</a> (%d)' "$group" "$group" "$gcount"
        [ -n "$atlas" ] && printf ' · <a href="%s/atlas.pdf">PDF atlas</a>' "$group"
        if [ -s "$contents.$group" ]; then printf '\n<ul>\n'; cat "$contents.$group"; printf '</ul>'; fi
        printf '</li>\n'
    } >> "$contents"
    rm -f "$contents.$group"
done
printf '<nav><ul id="contents">\n' >> "$index"
cat "$contents" >> "$index"
printf '<li><a href="#sources">Sources</a></li>\n</ul></nav>\n' >> "$index"
cat "$body" >> "$index"
rm -f "$body" "$contents"
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
<div id="viewer" hidden><p></p></div>
<script>
"use strict";
// the filter: the whole query as a phrase where some figure has it ("example 27", "fig. 2.12"),
// else every word of it, in a figure's name, title, citation, header or functions; a number
// matches only whole (2.12 is not 2.120)
const filter = document.getElementById("filter"), shown = document.getElementById("shown");
function pattern(text) {
  const esc = text.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
  return new RegExp((/^[0-9]/.test(text) ? "(?<![0-9.])" : "") + esc + (/[0-9]$/.test(text) ? "(?![0-9]|\\.[0-9])" : ""));
}
function apply() {
  const query = filter.value.toLowerCase().trim().replace(/\s+/g, " ");
  const figs = Array.from(document.querySelectorAll("figure"));
  const hay = f => f.dataset.search.replace(/\s+/g, " ") + " " + f.id.toLowerCase();
  let tests = [];
  if (query) {
    const phrase = pattern(query);
    tests = figs.some(f => phrase.test(hay(f))) ? [phrase] : query.split(" ").map(pattern);
  }
  let n = 0;
  for (const fig of figs) {
    const h = hay(fig), hit = tests.every(t => t.test(h));
    fig.hidden = !hit;
    if (hit) n++;
  }
  for (const book of document.querySelectorAll("section.book")) {
    book.hidden = !book.querySelector("figure:not([hidden])");
  }
  shown.textContent = query ? n + " of " + figs.length + " figures" : "";
  document.body.dataset.shown = String(n);
}
filter.addEventListener("input", apply);
if (location.search.startsWith("?q=")) { filter.value = decodeURIComponent(location.search.slice(3)); }
apply();
// a thumbnail opens large (the SVG, sharp at any size); a click or Escape closes it
const viewer = document.getElementById("viewer");
for (const a of document.querySelectorAll("a.zoom")) {
  a.addEventListener("click", e => {
    e.preventDefault();
    const img = viewer.querySelector("img") || viewer.insertBefore(document.createElement("img"), viewer.firstChild);
    img.src = a.getAttribute("href");
    img.alt = a.querySelector("img").alt;
    viewer.querySelector("p").textContent = a.closest("figure").querySelector("figcaption").firstChild.textContent;
    viewer.hidden = false;
  });
}
viewer.addEventListener("click", () => { viewer.hidden = true; });
document.addEventListener("keydown", e => { if (e.key === "Escape") viewer.hidden = true; });
</script>
</body></html>
HTML
mv "$index" "$out/index.html"
echo "gallery: $count examples rendered into $out (open index.html)"
[ "$failed" = 0 ]
