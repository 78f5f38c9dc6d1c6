#!/bin/sh
# The live page in headless Chromium (tests/cli/live_page.py, driven through the DevTools
# protocol): the page loads and shows the SVG, moving a slider changes the figure, an error in
# the edited script shows its line and the last figure stays.  Writes the page's screenshot to
# $PC_SCREENSHOT_LIVE (docs/live.png is one).  Skipped (77) only without a browser.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
if [ -z "$browser" ]; then
    echo "SKIP: no Chromium (./setup.sh installs Debian's chromium)"
    exit 77
fi
cat > live.lua <<'LUA'
local k = slider("k", 0, 1, .35)
local n = slider("n", 1, 8, 3, 1)
circle(320, 240, 50 + 150 * k, 14)
for i = 0, n - 1 do
  local a = 2 * math.pi * i / n
  line(320, 240, 320 + 200 * math.cos(a), 240 + 200 * math.sin(a), 10)
end
label(string.format("k = %.2f, n = %d", k, n), P(320, 460), "c", 15)
LUA
"$POINTCALC" serve "$WORK/live.lua" --port 0 > serve.txt 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; rm -rf "$WORK"' EXIT
for i in $(seq 50); do grep -q "http://127.0.0.1:" serve.txt && break; sleep .1; done
url=$(sed -n 's/.*\(http:\/\/127.0.0.1:[0-9]*\/\).*/\1/p' serve.txt)
run python3 "$here/live_page.py" "$browser" "$WORK/profile" "$url" "$WORK/live.lua" \
    "${PC_SCREENSHOT_LIVE:-$WORK/live.png}"
cat out.txt
expect_rc 0 "the live page in the browser ($(tail -1 out.txt))"
finish
