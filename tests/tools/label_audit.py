#!/usr/bin/env python3
"""Label audit of SVG figures: how many labels overlap each other, run off the picture, or
have a drawn stroke passing through them.

    label_audit.py [--each] FILE.svg ...

A label's box is its <text>'s cell: from x to x + textLength (without one, as the print look
writes its labels, half an em a character), and from the baseline up three quarters of the
font size to a quarter below (the VGA font's 12 of 16 rows above the baseline).  A label with
<tspan> runs (math: subscripts smaller and lower) is the union of its runs' boxes, each at its
own x, y and size.  The picture's size is its viewBox where it has one (the print look: width
and height in pt), else its width and height without a unit.  A stroke crosses a label when
one of its segments (path outlines, lines of
polylines, circles as 32-gons, outlined rectangles), cut to its group's clip rectangle, enters
the box shrunk by one pixel on every side, so a stroke that only touches the cell's edge does
not count.  Hidden groups and clip paths' own rectangles are not strokes.  Animated SVGs (with
<animate>) are skipped: their frames overlap by design.  Prints one line per file with --each,
then the totals as `labels N overlapping_pairs N outside N crossed N`.
"""
import math
import re
import sys
import xml.etree.ElementTree as ET

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def path_segments(d):
    """The segments of a path's outline (M L H V C Z and their relative forms; a cubic by
    its control polygon's chord approximation in 8 pieces)."""
    segs, x, y, sx, sy = [], 0.0, 0.0, 0.0, 0.0
    for cmd, args in re.findall(r"([MmLlHhVvCcZz])([^MmLlHhVvCcZz]*)", d):
        v = [float(t) for t in re.findall(NUM, args)]
        if cmd in "Zz":
            segs.append((x, y, sx, sy))
            x, y = sx, sy
            continue
        rel = cmd.islower()
        c = cmd.upper()
        step = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6}[c]
        for i in range(0, len(v) - step + 1, step):
            a = v[i:i + step]
            if c == "H":
                nx, ny = (x + a[0] if rel else a[0]), y
            elif c == "V":
                nx, ny = x, (y + a[0] if rel else a[0])
            elif c == "C":
                pts = [(a[k] + (x if rel else 0), a[k + 1] + (y if rel else 0)) for k in (0, 2, 4)]
                px, py = x, y
                for k in range(1, 9):
                    t = k / 8
                    u = 1 - t
                    qx = u**3 * x + 3 * u * u * t * pts[0][0] + 3 * u * t * t * pts[1][0] + t**3 * pts[2][0]
                    qy = u**3 * y + 3 * u * u * t * pts[0][1] + 3 * u * t * t * pts[1][1] + t**3 * pts[2][1]
                    segs.append((px, py, qx, qy))
                    px, py = qx, qy
                x, y = pts[2]
                continue
            else:
                nx, ny = (x + a[0], y + a[1]) if rel else (a[0], a[1])
            if c == "M" and i == 0:
                sx, sy = nx, ny
            else:
                segs.append((x, y, nx, ny))
            x, y = nx, ny
    return segs


def seg_hits_box(s, b):
    """Liang-Barsky: does segment s meet the open box b = (x0, y0, x1, y1)?"""
    x0, y0, x1, y1 = s
    t0, t1 = 0.0, 1.0
    dx, dy = x1 - x0, y1 - y0
    for p, q in ((-dx, x0 - b[0]), (dx, b[2] - x0), (-dy, y0 - b[1]), (dy, b[3] - y0)):
        if p == 0:
            if q <= 0:
                return False
        else:
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
            if t0 >= t1:
                return False
    return True


def length(v):
    """An SVG length: a number with an optional unit ("226.772pt", "640", "12px"), in the
    SVG's user units as they are written."""
    m = re.match(r"\s*(" + NUM + r")", v or "")
    if not m:
        raise ValueError("not a length: %r" % v)
    return float(m.group(1))


def tag(e):
    return e.tag.split("}")[-1]


def clip_segment(s, c):
    """The part of segment s inside the rectangle c (x0, y0, x1, y1), or None."""
    if c is None:
        return s
    x0, y0, x1, y1 = s
    t0, t1 = 0.0, 1.0
    dx, dy = x1 - x0, y1 - y0
    for p, q in ((-dx, x0 - c[0]), (dx, c[2] - x0), (-dy, y0 - c[1]), (dy, c[3] - y0)):
        if p == 0:
            if q < 0:
                return None
        else:
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
    if t0 > t1:
        return None
    return (x0 + t0 * dx, y0 + t0 * dy, x0 + t1 * dx, y0 + t1 * dy)


def shapes(e, clip, clips, boxes, segs):
    """Walk the tree: labels' boxes, and the stroke segments cut to their group's clip."""
    t = tag(e)
    if t in ("clipPath", "defs"):
        return
    if e.get("visibility") == "hidden":
        return
    cp = e.get("clip-path")
    if cp:
        clip = clips.get(cp[5:-1], clip)
    mine = []
    if t == "text":
        # one label: the element's own text and its <tspan> runs (a math label's subscripts are
        # smaller and lower), each at its x, y (a run without one follows the one before) and
        # font size; the label's box is the union of theirs
        runs = [(e, e.text)] + [(r, r.text) for r in e.iter() if r is not e and tag(r) == "tspan"]
        fs0, bs, x, y = length(e.get("font-size", "16")), [], None, None
        for r, txt in runs:
            x = length(r.get("x")) if r.get("x") is not None else x
            y = length(r.get("y")) if r.get("y") is not None else y
            if not (txt or "").strip() or x is None or y is None:
                continue
            fs = length(r.get("font-size")) if r.get("font-size") else fs0
            w = length(r.get("textLength")) if r.get("textLength") else 0.5 * fs * len(txt)
            bs.append((x, y - 0.75 * fs, x + w, y + 0.25 * fs))
            x += w
        if bs:
            boxes.append((min(b[0] for b in bs), min(b[1] for b in bs),
                          max(b[2] for b in bs), max(b[3] for b in bs)))
        return
    elif t == "path":
        mine = path_segments(e.get("d", ""))
    elif t == "line":
        mine = [tuple(float(e.get(k, "0")) for k in ("x1", "y1", "x2", "y2"))]
    elif t in ("circle", "ellipse"):
        cx, cy = float(e.get("cx", "0")), float(e.get("cy", "0"))
        rx = float(e.get("r", e.get("rx", "0")))
        ry = float(e.get("r", e.get("ry", "0")))
        pts = [(cx + rx * math.cos(2 * math.pi * k / 32), cy + ry * math.sin(2 * math.pi * k / 32))
               for k in range(33)]
        mine = [(pts[k][0], pts[k][1], pts[k + 1][0], pts[k + 1][1]) for k in range(32)]
    elif t == "rect" and e.get("x") is not None:   # not the background
        x, y = float(e.get("x")), float(e.get("y"))
        w, h = float(e.get("width")), float(e.get("height"))
        mine = [(x, y, x + w, y), (x + w, y, x + w, y + h), (x + w, y + h, x, y + h), (x, y + h, x, y)]
    for sg in mine:
        sg = clip_segment(sg, clip)
        if sg:
            segs.append(sg)
    for child in e:
        shapes(child, clip, clips, boxes, segs)


def audit(path):
    root = ET.parse(path).getroot()
    if any(tag(e) == "animate" for e in root.iter()):
        return None
    vb = root.get("viewBox")
    if vb:   # the print look: width and height in pt, the drawing in the viewBox's units
        width, height = [float(v) for v in re.findall(NUM, vb)[2:4]]
    else:
        width, height = length(root.get("width", "640")), length(root.get("height", "480"))
    clips = {}
    for e in root.iter():
        if tag(e) == "clipPath":
            r = next((c for c in e if tag(c) == "rect"), None)
            if r is not None:
                x, y = float(r.get("x", "0")), float(r.get("y", "0"))
                clips[e.get("id")] = (x, y, x + float(r.get("width")), y + float(r.get("height")))
    boxes, segs = [], []
    shapes(root, None, clips, boxes, segs)
    overlaps = sum(1 for i in range(len(boxes)) for j in range(i + 1, len(boxes))
                   if boxes[i][0] < boxes[j][2] and boxes[j][0] < boxes[i][2]
                   and boxes[i][1] < boxes[j][3] and boxes[j][1] < boxes[i][3])
    outside = sum(1 for b in boxes if b[0] < 0 or b[1] < 0 or b[2] > width or b[3] > height)
    crossed = 0
    for b in boxes:
        inner = (b[0] + 1, b[1] + 1, b[2] - 1, b[3] - 1)
        if any(seg_hits_box(s, inner) for s in segs
               if max(s[0], s[2]) > inner[0] and min(s[0], s[2]) < inner[2]
               and max(s[1], s[3]) > inner[1] and min(s[1], s[3]) < inner[3]):
            crossed += 1
    return len(boxes), overlaps, outside, crossed


def main(argv):
    each = "--each" in argv
    files = [a for a in argv if a != "--each"]
    tot = [0, 0, 0, 0]
    for f in files:
        r = audit(f)
        if r is None:
            continue
        if each:
            print(f, "labels %d overlapping_pairs %d outside %d crossed %d" % r)
        tot = [a + b for a, b in zip(tot, r)]
    print("labels %d overlapping_pairs %d outside %d crossed %d" % tuple(tot))


if __name__ == "__main__":
    main(sys.argv[1:])
