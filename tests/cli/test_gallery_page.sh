#!/bin/sh
# The gallery page in a browser: examples/render_gallery.sh renders every example, then headless
# Chromium opens tests/cli/gallery_check.html beside it, which loads every image, SVG and script
# the page shows or links and checks its anchors and each figure's links; the browser's log must
# hold no console message from the page. A damaged copy of the gallery must fail the same check.
# Writes a screenshot of the page to $PC_SCREENSHOT (default: gallery-page.png beside the
# program; docs/gallery_page.png in the README is one). Skipped (77) only without a browser.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"

browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
if [ -z "$browser" ]; then
    echo "SKIP: no Chromium (./setup.sh installs Debian's chromium)"
    exit 77
fi
shot=${PC_SCREENSHOT:-$(dirname "$POINTCALC")/gallery-page.png}

# browse URL [flags...]: headless Chromium with its own profile, its log in browser.log
browse() {
    url=$1; shift
    "$browser" --headless --no-sandbox --disable-gpu --user-data-dir="$WORK/profile" \
        --no-first-run --enable-logging=stderr --v=0 --virtual-time-budget=30000 "$@" "$url" \
        2>browser.log
}
# check DIR: the checker's verdict on DIR/gallery, in verdict.txt; console messages in console.txt
check() {
    cp "$PC_SOURCE_DIR/tests/cli/gallery_check.html" "$1/check.html"
    browse "file://$1/check.html" --allow-file-access-from-files --dump-dom >dom.html
    sed -n '/<pre id="result">/,/<\/pre>/p' dom.html | sed 's/<[^>]*>//g' >verdict.txt
    grep 'CONSOLE' browser.log | grep -v "source: file://$1/check.html" >console.txt
}

mkdir site
run env PC_GALLERY_PDF=0 sh "$PC_SOURCE_DIR/examples/render_gallery.sh" "$POINTCALC" site/gallery   # the atlas: test_gallery_atlas.sh
expect_rc 0 "render_gallery.sh renders every example"
nscripts=$(ls "$PC_SOURCE_DIR"/examples/*/*.lua | wc -l)
nfigures=$(ls site/gallery/*/*.png | wc -l)
expect_eq "$nfigures" "$nscripts" "one PNG per example script"

check "$WORK/site"
expect_in verdict.txt "OK figures=$nscripts png=$nscripts svg=$nscripts scripts=$nscripts " \
    "every figure's image, SVG and script load and every anchor has its target"
expect_in verdict.txt " pages=$nscripts" "every figure links its own page, and the page loads"
nanimated=$(grep -l "animate = true" "$PC_SOURCE_DIR"/examples/*/*.lua | wc -l)
expect_in verdict.txt " animations=$nanimated" "each animated example links its animated SVG (docs/live.md)"
checks=$((checks + 1))
[ -s console.txt ] && fail "console messages from the gallery page: $(head -5 console.txt)"
# every Stepanov example links its section of the article (the checker also asks each figure)
nstepanov=$(ls "$PC_SOURCE_DIR"/examples/stepanov/*.lua | wc -l)
expect_eq "$(grep -c 'href="#src-stepanov-[2-7]"' site/gallery/index.html)" "$nstepanov" \
    "each Stepanov figure cites its section"
expect_in site/gallery/index.html '>Stepanov 2013, §2, example 2</a>' "example 2's citation"
expect_in site/gallery/index.html '<li id="src-stepanov-2">' "the section the citations link"
expect_in site/gallery/index.html '"#src-buimov">Buimov 2012, §2.8.4, Fig. 2.12</a>' \
    "a textbook citation from a script's header"

# the page used as a reader would: contents, the filter, large views, a figure's page
expect_eq "$(ls site/gallery/*/*.html | wc -l)" "$nscripts" "a page per figure"
run python3 "$PC_SOURCE_DIR/tests/cli/gallery_page.py" "$browser" "$WORK/profile2" "$WORK/site/gallery"
cat out.txt
expect_rc 0 "the gallery page in the browser: $(grep FAIL out.txt | head -3) $(tail -3 err.txt)"

# the screenshot for the README: a PNG of the requested size
browse "file://$WORK/site/gallery/index.html" --hide-scrollbars --window-size=1280,1000 \
    --screenshot="$shot" >/dev/null
expect_file "$shot" "screenshot written"
expect_eq "$(od -An -tx1 -j16 -N8 "$shot" 2>/dev/null | tr -d ' \n')" "00000500000003e8" \
    "screenshot is 1280x1000"

# the same check on a damaged copy must find each fault: a missing PNG, an SVG that is not one,
# a figure without its script link and a script error on the page
mkdir bad
cp -r site/gallery bad/gallery
rm bad/gallery/stepanov/05_two_point_curve.png
echo "not an svg" > bad/gallery/stepanov/06_curves_through_polygons.svg
sed -i 's|<a href="stepanov/07_power_half_splines.lua">script</a>|script|; s|</body>|<script>no_such_function()</script></body>|' \
    bad/gallery/index.html
check "$WORK/bad"
expect_in verdict.txt "FAIL" "the damaged gallery fails"
expect_in verdict.txt "image stepanov/05_two_point_curve.png does not load" "a missing PNG is found"
expect_in verdict.txt "link stepanov/06_curves_through_polygons.svg does not load" "a broken SVG is found"
expect_in verdict.txt "figure stepanov/07_power_half_splines does not link its lua" "a missing script link is found"
expect_in console.txt "no_such_function" "a console error is found"
finish
