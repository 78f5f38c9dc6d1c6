"""Latency of the live page: for each script, `pointcalc serve` is started and the time from
a slider change (a /render request with new values) to the complete SVG is measured; reports
the median and the worst over the renders of each script and over all.
    python3 bench/live.py POINTCALC SCRIPT... [--renders N]"""
import re, statistics, subprocess, sys, time, urllib.error, urllib.request

args = sys.argv[1:]
renders = 10
if "--renders" in args:
    i = args.index("--renders")
    renders = int(args[i + 1])
    del args[i:i + 2]
pc, scripts = args[0], args[1:]
all_ms = []
rows = []
for script in scripts:
    server = subprocess.Popen([pc, "serve", script, "--port", "0"], stdout=subprocess.PIPE, text=True)
    try:
        url = re.search(r"(http://127\.0\.0\.1:\d+/)", server.stdout.readline()).group(1)
        params = urllib.request.urlopen(url + "params", timeout=30).read()
        names = re.findall(rb'"name": "(\w+)", "min": ([-\d.e]+), "max": ([-\d.e]+)', params)
        ms = []
        for k in range(renders):
            q = "&".join(f"{n.decode()}={float(lo) + (float(hi) - float(lo)) * k / max(renders - 1, 1)}"
                         for n, lo, hi in names)
            start = time.perf_counter()
            try:
                body = urllib.request.urlopen(url + "render?" + q, timeout=30).read()
            except urllib.error.HTTPError as e:
                sys.exit(f"{script}: the render failed: {e.read().decode(errors='replace')}")
            ms.append((time.perf_counter() - start) * 1e3)
        rows.append((script.split("/")[-1], statistics.median(ms), max(ms)))
        all_ms += ms
    finally:
        server.terminate()
        server.wait()
w = max(len(r[0]) for r in rows)
for name, med, worst in rows:
    print(f"{name:<{w}}  median {med:7.1f} ms  worst {worst:7.1f} ms")
print(f"{'all':<{w}}  median {statistics.median(all_ms):7.1f} ms  worst {max(all_ms):7.1f} ms"
      f"  ({len(all_ms)} renders of {len(rows)} scripts)")
