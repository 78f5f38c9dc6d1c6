#!/usr/bin/env python3
"""inkdiff A B [RADIUS [THRESHOLD]]: do two renderings of one figure on white agree as line
drawings?  A and B are PNG (8-bit RGB or RGBA, not interlaced) or binary PPM files of one size.
Ink is a pixel darker than mid-grey.  Prints the share of each picture's ink within RADIUS
pixels (default 2) of the other's, exits 0 when both reach THRESHOLD (default 0.95), 1 when
not, 2 on bad input.  A test tool of the print-look tests, not part of the product."""
import struct, sys, zlib

def read_png(data):
    pos, chunks = 8, b""
    w = h = ctype = 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError("unsupported PNG")
        elif kind == b"IDAT":
            chunks += body
        pos += 12 + n
    bpp = 3 if ctype == 2 else 4
    raw, stride = zlib.decompress(chunks), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    ink = set()
    for y, line in enumerate(rows):
        for x in range(w):
            px = line[x * bpp:x * bpp + bpp]
            alpha = px[3] if bpp == 4 else 255
            luma = (px[0] * 3 + px[1] * 6 + px[2]) / 10 * alpha / 255 + 255 * (1 - alpha / 255)
            if luma < 128: ink.add((x, y))
    return w, h, ink

def read_ppm(data):
    header = b" ".join(l.split(b"#")[0] for l in data.split(b"\n", 4)[:4]).split()
    w, h = int(header[1]), int(header[2])
    px = data[len(data) - w * h * 3:]
    ink = {(i % w, i // w) for i in range(w * h)
           if (px[3 * i] * 3 + px[3 * i + 1] * 6 + px[3 * i + 2]) / 10 < 128}
    return w, h, ink

def load(path):
    data = open(path, "rb").read()
    return read_png(data) if data[:8] == b"\x89PNG\r\n\x1a\n" else read_ppm(data)

def share(a, b, r):
    if not a: return 1.0
    offs = [(dx, dy) for dx in range(-r, r + 1) for dy in range(-r, r + 1) if dx * dx + dy * dy <= r * r]
    near = sum(1 for (x, y) in a if any((x + dx, y + dy) in b for dx, dy in offs))
    return near / len(a)

try:
    wa, ha, a = load(sys.argv[1])
    wb, hb, b = load(sys.argv[2])
except Exception as e:
    print("inkdiff:", e, file=sys.stderr)
    sys.exit(2)
r = int(sys.argv[3]) if len(sys.argv) > 3 else 2
t = float(sys.argv[4]) if len(sys.argv) > 4 else 0.95
if (wa, ha) != (wb, hb):
    print("inkdiff: sizes differ: %dx%d and %dx%d" % (wa, ha, wb, hb))
    sys.exit(1)
sa, sb = share(a, b, r), share(b, a, r)
print("ink %d and %d pixels; within %d px: %.3f and %.3f" % (len(a), len(b), r, sa, sb))
sys.exit(0 if sa >= t and sb >= t and a and b else 1)
