"""The live page in headless Chromium (tests/cli/test_live_page.sh): the page loads and shows
the figure as SVG with a slider per parameter, scaled to the window, the script beside it;
moving a slider (mouse or keyboard) changes the figure; sliders show their step's precision;
the figure downloads as SVG and PNG; an error in the edited script shows its line on the page,
marked in the script, while the last figure stays.
    python3 live_page.py CHROMIUM PROFILE_DIR URL SCRIPT [SCREENSHOT]"""
import base64, json, os, struct, sys, time, urllib.error, urllib.request
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
    check(page.eval("document.getElementById('slider-k').nextSibling.value") == "0.90",
          "the slider's value is shown with its precision (a hundredth of 0..1)")
    check(page.eval("document.getElementById('slider-n').nextSibling.value") == "3",
          "an integer slider shows an integer")
    params = json.load(urllib.request.urlopen(url + "params"))["params"]
    check([(p["name"], p["min"], p["max"], p["default"], p["step"]) for p in params] ==
          [("k", 0, 1, 0.35, 0), ("n", 1, 8, 3, 1)], "/params gives the declared numbers: " + repr(params))
    raw = urllib.request.urlopen(url + "params").read().decode()
    check('"default": 0.35,' in raw and "0.3499" not in raw, "/params writes 0.35 as 0.35: " + raw)

    # the keyboard: focus the slider n, the right arrow steps it to 4 and re-renders
    rendered = page.eval("Number(document.body.dataset.rendered)")
    page.eval("document.getElementById('slider-n').focus()")
    for kind in ("rawKeyDown", "keyUp"):
        page.call("Input.dispatchKeyEvent", type=kind, key="ArrowRight", code="ArrowRight",
                  windowsVirtualKeyCode=39, nativeVirtualKeyCode=39)
    check(page.wait(f"Number(document.body.dataset.rendered) > {rendered}"), "the arrow key re-renders")
    check(page.eval("document.getElementById('slider-n').nextSibling.value") == "4",
          "the arrow key steps the integer slider to 4")

    # the script beside the figure, line by line
    lines = open(script).read().rstrip("\n").split("\n")
    check(page.eval("document.querySelectorAll('#script span').length") == len(lines),
          "the script is shown, one line per line")
    check(page.eval("document.querySelectorAll('#script span')[2].textContent") == lines[2],
          "the script's third line")

    # the figure scales to the window: at 1280 and at 1600 wide it fills its pane
    widths = []
    for w in (1280, 1600):
        page.call("Emulation.setDeviceMetricsOverride", width=w, height=900, deviceScaleFactor=1, mobile=False)
        time.sleep(0.3)
        fig = page.eval("document.querySelector('#figure svg').getBoundingClientRect().width")
        pane = page.eval("document.getElementById('figure').getBoundingClientRect().width")
        side = page.eval("document.getElementById('script').getBoundingClientRect().left")
        widths.append(fig)
        check(fig > 0.95 * pane and fig > 640, f"at {w} px the figure fills its pane ({fig:.0f} of {pane:.0f})")
        check(side >= page.eval("document.querySelector('#figure svg').getBoundingClientRect().right"),
              f"at {w} px the script is beside the figure")
    check(widths[1] > widths[0], "a wider window gives a larger figure: " + repr(widths))
    page.call("Emulation.clearDeviceMetricsOverride")

    # downloads: SVG from the page, PNG from the server, into a folder of the test
    folder = os.path.join(os.path.dirname(script), "downloads")
    os.makedirs(folder, exist_ok=True)
    page.call("Browser.setDownloadBehavior", behavior="allow", downloadPath=folder)
    for fmt in ("svg", "png"):
        page.eval(f"document.getElementById('download-{fmt}').click()")
        path = os.path.join(folder, "live." + fmt)
        for _ in range(100):
            if os.path.exists(path) and os.path.getsize(path) > 0:
                break
            time.sleep(0.1)
        time.sleep(0.2)
        data = open(path, "rb").read() if os.path.exists(path) else b""
        if fmt == "svg":
            check(data.startswith(b"<svg") and b"#ffff55" in data, "the SVG download is the figure")
        else:
            ok = data[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", data[16:24]) == (640, 480)
            check(ok, "the PNG download is a 640x480 PNG")
    # PDF: offered exactly when the server renders it (the print renderer); then it downloads
    try:
        r = urllib.request.urlopen(url + "render?format=pdf")
        has_pdf = "pdf" in r.headers.get("Content-Type", "")
    except urllib.error.HTTPError:
        has_pdf = False
    check(page.eval("document.getElementById('download-pdf').hidden") == (not has_pdf),
          f"the PDF button shows only where the server writes PDF (here: {has_pdf})")
    if has_pdf:
        page.eval("document.getElementById('download-pdf').click()")
        path = os.path.join(folder, "live.pdf")
        for _ in range(100):
            if os.path.exists(path) and os.path.getsize(path) > 0:
                break
            time.sleep(0.1)
        check(open(path, "rb").read(5) == b"%PDF-", "the PDF download is a PDF")
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
    check(page.wait("document.querySelector('#script span.failing') !== null"), "the failing line is marked")
    check(page.eval("Array.from(document.querySelectorAll('#script span')).findIndex(s => s.classList.contains('failing'))") == 2,
          "the marked line is line 3")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
