"""The live page in headless Chromium (tests/cli/test_live_page.sh): the page loads and shows
the figure as SVG with a slider per parameter; moving a slider changes the figure; an error in
the edited script shows its line on the page while the last figure stays.
    python3 live_page.py CHROMIUM PROFILE_DIR URL SCRIPT [SCREENSHOT]"""
import base64, sys, time
from cdp import Browser

chromium, profile, url, script = sys.argv[1:5]
shot = sys.argv[5] if len(sys.argv) > 5 else None
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


with Browser(chromium, profile) as b:
    page = b.open(url)
    check(page.wait("document.querySelector('#figure svg') !== null"), "the page shows the figure as SVG")
    check(page.eval("document.getElementById('slider-k') !== null"), "a slider for k")
    check(page.eval("document.getElementById('slider-n') !== null"), "a slider for n")
    before = page.eval("document.getElementById('figure').innerHTML")
    rendered = page.eval("Number(document.body.dataset.rendered)")
    page.eval("""(() => { const s = document.getElementById('slider-k');
                   s.value = 0.9; s.dispatchEvent(new Event('input')); })()""")
    check(page.wait(f"Number(document.body.dataset.rendered) > {rendered} && "
                    "document.getElementById('figure').innerHTML !== " + repr(before)),
          "moving the slider changes the figure")
    check(page.eval("document.getElementById('slider-k').nextSibling.value") == "0.9000",
          "the slider's value is shown")
    if shot:
        data = page.call("Page.captureScreenshot", format="png")["data"]
        open(shot, "wb").write(base64.b64decode(data))
    good = page.eval("document.getElementById('figure').innerHTML")
    time.sleep(1.1)   # a new modification time
    with open(script, "w") as f:
        f.write('local k = slider("k", 0, 1, .5)\nlocal n = slider("n", 1, 8, 3, 1)\n'
                'circle(320, 240, nil + k)\n')
    check(page.wait("!document.getElementById('error').hidden", 10), "an error shows on the page")
    text = page.eval("document.getElementById('error').textContent")
    check(":3:" in text and "live.lua" in text, "the error names the script's line: " + repr(text))
    check(page.eval("document.getElementById('figure').innerHTML") == good, "the last good figure stays")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
