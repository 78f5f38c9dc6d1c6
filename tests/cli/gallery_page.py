"""The gallery page in headless Chromium (tests/cli/test_gallery_page.sh): the contents list
each book with its chapters, the filter finds figures by figure number, title and function,
thumbnails are legible (at least 360 px wide) and open large on a click, and a figure's own
page shows its script and citation.
    python3 gallery_page.py CHROMIUM PROFILE_DIR GALLERY_DIR"""
import os, sys, time
from cdp import Browser

chromium, profile, gallery = sys.argv[1:4]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def visible(page):
    return page.eval("Array.from(document.querySelectorAll('figure')).filter(f => !f.hidden).map(f => f.id)")


def type_filter(page, text):
    page.eval("(() => { const f = document.getElementById('filter'); f.focus(); f.value = ''; "
              "f.dispatchEvent(new Event('input')); })()")
    page.call("Input.insertText", text=text)
    time.sleep(0.2)


with Browser(chromium, profile) as b:
    page = b.open("file://" + os.path.join(gallery, "index.html"))
    check(page.wait("document.querySelectorAll('figure').length > 100"), "the page lists the figures")
    # the page is large (300 figures): count them once it has loaded, not while it parses
    check(page.wait("document.readyState === 'complete'", 30), "the page loads")
    total = page.eval("document.querySelectorAll('figure').length")
    books = page.eval("Array.from(document.querySelectorAll('#contents > li > a')).map(a => a.textContent)")
    check(books == ["basics", "buimov", "konopatsky", "korotky", "stepanov", "Sources"], "the contents: " + repr(books))
    sections = page.eval("Array.from(document.querySelectorAll('#contents a[href^=\"#stepanov-\"]')).map(a => a.textContent)")
    check(sections == ["§2", "§3", "§4", "§5", "§6", "§7"], "Stepanov's sections in the contents: " + repr(sections))
    check(page.eval("document.querySelector('#contents a[href=\"#stepanov-09_taurus\"]').textContent") == "§3",
          "§3 links its first example (9)")

    # the filter: by figure number, by title, by function
    type_filter(page, "fig. 2.12")
    shown = visible(page)
    check(sorted(shown) == ["basics-04_cube_projections", "buimov-f2_12_rotated_two_point",
                            "konopatsky-f2_12_hyperbola_focal"],
          "'fig. 2.12' finds Buimov's Fig. 2.12 and Konopatsky's: " + repr(shown))
    check(page.eval("document.getElementById('stepanov').hidden"), "a book without a match is hidden")
    check(page.eval("document.getElementById('shown').textContent") == f"3 of {total} figures",
          "the count of figures shown")
    type_filter(page, "2.12")
    shown = visible(page)
    check("basics-04_cube_projections" in shown and "konopatsky-f2_12_hyperbola_focal" in shown and
          "konopatsky-23_redundant" not in shown, "'2.12' finds Fig. 2.12, not (2.120): " + repr(shown))
    type_filter(page, "example 27")
    check(visible(page) == ["stepanov-27_circles_into_square", "stepanov-27b_almost_square_without_corners"],
          "'example 27' finds Stepanov's example 27 and its variant: " + repr(visible(page)))
    type_filter(page, "korotky.elastic")
    shown = visible(page)
    check(len(shown) >= 1 and all(s.startswith("korotky-") for s in shown), "a function finds the figures that call it: " + repr(shown))
    type_filter(page, "oval")
    check("stepanov-02_oval_in_quadrilateral" in visible(page), "a word of the title")
    type_filter(page, "")
    check(len(visible(page)) == total, "an empty filter shows every figure")

    # legible previews, larger on demand
    page.call("Emulation.setDeviceMetricsOverride", width=1280, height=1000, deviceScaleFactor=1, mobile=False)
    time.sleep(0.3)
    w = page.eval("document.querySelector('#stepanov-02_oval_in_quadrilateral img').getBoundingClientRect().width")
    check(w >= 360, f"a thumbnail is at least 360 px wide ({w:.0f})")
    page.eval("document.querySelector('#stepanov-02_oval_in_quadrilateral a.zoom').click()")
    check(page.wait("!document.getElementById('viewer').hidden"), "a click on a thumbnail opens it large")
    check(page.eval("document.querySelector('#viewer img').getAttribute('src')") == "stepanov/02_oval_in_quadrilateral.svg",
          "the large view is the SVG")
    check(page.wait("document.querySelector('#viewer img').getBoundingClientRect().width > 1000"),
          "the large view fills the window")
    page.call("Input.dispatchKeyEvent", type="keyDown", key="Escape", code="Escape", windowsVirtualKeyCode=27)
    check(page.wait("document.getElementById('viewer').hidden"), "Escape closes it")

    # a figure's page
    page = b.open("file://" + os.path.join(gallery, "buimov", "f4_03c_spline_ends.html"))
    check(page.wait("document.querySelector('pre code') !== null"), "the figure's page shows its script")
    script = open(os.path.join(gallery, "buimov", "f4_03c_spline_ends.lua")).read()
    check(page.eval("document.querySelector('pre code').textContent") == script, "the script as it is")
    check("Buimov 2012, §4.2" in page.eval("document.body.textContent"), "the page cites the book")
    check(page.eval("document.querySelector('img').getAttribute('src')") == "f4_03c_spline_ends.svg", "the page shows the SVG")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
