#!/bin/sh
# Sliders, --set, animation frames and the live page (docs/live.md): `pointcalc serve` on a
# free port answers /params, /render and /version over HTTP; a render equals the headless
# render of the same values byte for byte; errors show their line; a runaway script is stopped;
# frame k equals the render at the k-th value of the animated slider.
. "$(dirname "$0")/lib.sh"

cat > live.lua <<'EOF'
local k = slider("k", 0, 1, .5)
local n = slider("n", 1, 8, 3, 1)
circle(320, 240, 50 + 150 * k, 14)
for i = 0, n - 1 do
  local a = 2 * math.pi * i / n
  line(320, 240, 320 + 200 * math.cos(a), 240 + 200 * math.sin(a), 10)
end
EOF

# --set: the value reaches the slider; bad forms are usage errors; out of range is the script's
run "$POINTCALC" live.lua --set k=0.25 --set n=5 -o set.svg
expect_rc 0 "--set renders"
run "$POINTCALC" live.lua -o default.svg
expect_rc 0 "defaults render"
checks=$((checks + 1)); cmp -s set.svg default.svg && fail "--set changed nothing"
run "$POINTCALC" live.lua --set k
expect_rc 2 "--set without a value"
expect_in err.txt "--set needs name=value" "the usage message"
run "$POINTCALC" live.lua --set k=2 -o x.svg
expect_rc 1 "--set outside the slider's range"
expect_in err.txt "live.lua:1: slider: the value 2 set for k is outside its range [0, 1]" "range message"

# frames: frame k is the render at the k-th value, pixel for pixel (the same PNG bytes)
cat > anim.lua <<'EOF'
local t = slider("t", 0, 2, 0, {animate = true})
circle(320, 240, 20 + 100 * t, 12)
line(0, 0, 320 * t, 240 * t, 10)
EOF
run "$POINTCALC" anim.lua --frames 5 -o fr.png -o fr.svg
expect_rc 0 "five frames"
expect_file fr-000.png "frame 0"
expect_file fr-004.png "frame 4"
expect_no_file fr-005.png "no sixth frame"
run "$POINTCALC" anim.lua --set t=1.5 -o at.png
checks=$((checks + 1)); cmp -s fr-003.png at.png || fail "frame 3 differs from the render at t = 1.5"
checks=$((checks + 1)); cmp -s fr-002.png at.png && fail "frame 2 should differ from t = 1.5"
checks=$((checks + 1)); xmllint --noout fr.svg 2>err.txt || fail "the animated SVG is not well-formed"
expect_in fr.svg 'calcMode="discrete"' "the SVG frames take turns"
checks=$((checks + 1)); [ "$(grep -c '<g visibility=' fr.svg)" = 5 ] || fail "five frame groups in the SVG"
run "$POINTCALC" live.lua --frames 3 -o x.png
expect_rc 1 "frames without an animated slider"
expect_in err.txt "declares no animated parameter" "its message"
run "$POINTCALC" anim.lua --frames 0 -o x.png
expect_rc 2 "--frames 0"

# the server: a free port, the page, the sliders, renders equal to headless ones
"$POINTCALC" serve live.lua --port 0 > serve.txt 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; rm -rf "$WORK"' EXIT
for i in $(seq 50); do grep -q "http://127.0.0.1:" serve.txt && break; sleep .1; done
url=$(sed -n 's/.*\(http:\/\/127.0.0.1:[0-9]*\/\).*/\1/p' serve.txt)
checks=$((checks + 1)); [ -n "$url" ] || fail "serve printed no address: $(cat serve.txt)"
get() {  # get PATH OUT: the body in OUT, the status in $code
    code=$(python3 - "$url$1" "$2" <<'PY'
import sys, urllib.request, urllib.error
try:
    r = urllib.request.urlopen(sys.argv[1], timeout=10); body = r.read(); code = r.status
except urllib.error.HTTPError as e:
    body = e.read(); code = e.code
open(sys.argv[2], "wb").write(body); print(code)
PY
)
}
get "" page.html
expect_eq "$code" 200 "the page"
expect_in page.html "pointcalc live" "the page's title"
get params params.json
expect_eq "$code" 200 "/params"
expect_in params.json '"name": "k", "min": 0, "max": 1, "default": 0.5' "slider k declared"
expect_in params.json '"name": "n", "min": 1, "max": 8, "default": 3, "step": 1' "slider n declared"
expect_in params.json '"error": null' "no error"
get "render?k=0.25&n=5" render.svg
expect_eq "$code" 200 "/render"
checks=$((checks + 1)); cmp -s render.svg set.svg || fail "the page's render differs from the headless one"
# the downloads: PNG and PDF are the bytes -o writes for the same values
run "$POINTCALC" live.lua --set k=0.25 --set n=5 -o set.png -o set.pdf
get "render?k=0.25&n=5&format=png" render.png
expect_eq "$code" 200 "/render as PNG"
checks=$((checks + 1)); cmp -s render.png set.png || fail "the page's PNG differs from the headless one"
get "render?k=0.25&n=5&format=pdf" render.pdf
expect_eq "$code" 200 "/render as PDF"
checks=$((checks + 1)); head -c 5 render.pdf | grep -q '%PDF-' || fail "the PDF download is no PDF"
checks=$((checks + 1))
[ "$(wc -c < render.pdf)" -gt 500 ] && [ "$(head -c 5 set.pdf)" = "%PDF-" ] || fail "the PDF download is too small"
get "render?format=gif" bad.txt
expect_eq "$code" 400 "an unknown format"
expect_in bad.txt "format=svg|png|pdf" "names the formats"
get "render?k=7" bad.txt
expect_eq "$code" 422 "a value outside the range"
expect_in bad.txt "live.lua:1: slider: the value 7 set for k is outside its range" "its message"
get "render?k=abc" bad.txt
expect_eq "$code" 400 "a value that is not a number"
get version v1.txt
sleep 1.1
printf 'local k = slider("k", 0, 1, .5)\ncircle(320, 240, 10, nil + 1)\n' > live.lua
get version v2.txt
checks=$((checks + 1)); cmp -s v1.txt v2.txt && fail "/version did not change when the script did"
get render err.txt
expect_eq "$code" 422 "an error in the edited script"
expect_in err.txt "live.lua:2:" "the error names its line"
printf 'local k = slider("k", 0, 1, .5)\nwhile true do end\n' > live.lua
start=$(date +%s)
get render loop.txt
expect_eq "$code" 422 "a runaway script is stopped"
expect_in loop.txt "time limit" "and says why"
checks=$((checks + 1)); [ $(( $(date +%s) - start )) -le 5 ] || fail "the runaway script was not stopped in time"
get nothing nf.txt
expect_eq "$code" 404 "an unknown path"
kill $server
finish
