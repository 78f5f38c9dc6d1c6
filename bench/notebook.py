"""A notebook cell that draws a typical gallery figure (Stepanov's example 2, the oval in a
quadrilateral: 1001 points, four lines), timed from execute request to the figure's arrival over
the Jupyter protocol, against two baselines in the same run: an empty cell through the same
kernel (the protocol's own cost) and the same script as a whole `pointcalc script -o x.svg`
process. Medians of 30.
    python3 bench/notebook.py POINTCALC SOURCE_DIR"""
import os, shutil, statistics, subprocess, sys, tempfile, time
from jupyter_client.manager import start_new_kernel

pc, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
script = os.path.join(src, "examples", "stepanov", "02_oval_in_quadrilateral.lua")
tmp = tempfile.mkdtemp()
spec = os.path.join(tmp, "kernels", "pointcalc")
shutil.copytree(os.path.join(src, "interp", "jupyter"), spec)
os.environ.update(JUPYTER_PATH=tmp, POINTCALC=pc, PYDEVD_DISABLE_FILE_VALIDATION="1")
km, kc = start_new_kernel(kernel_name="pointcalc", startup_timeout=60)


def cell(code):
    t = time.perf_counter()
    msg_id = kc.execute(code)
    figure = False
    while True:
        m = kc.get_iopub_msg(timeout=30)
        if m["parent_header"].get("msg_id") != msg_id:
            continue
        figure |= m["msg_type"] == "display_data"
        if m["msg_type"] == "status" and m["content"]["execution_state"] == "idle":
            return time.perf_counter() - t, figure


figure_code = open(script).read()
cell("x = 1")
empty = [cell("x = 1")[0] for _ in range(30)]
draws = []
for _ in range(30):
    dt, fig = cell("screen(12)\n" + figure_code)
    assert fig, "the cell did not return a figure"
    draws.append(dt)
procs = []
for _ in range(30):
    t = time.perf_counter()
    subprocess.run([pc, script, "-o", os.path.join(tmp, "x.svg")], check=True)
    procs.append(time.perf_counter() - t)
kc.stop_channels()
km.shutdown_kernel(now=True)
shutil.rmtree(tmp, ignore_errors=True)
ms = lambda xs: statistics.median(xs) * 1000
print(f"notebook cell drawing example 2: median {ms(draws):.1f} ms (worst {max(draws) * 1000:.1f} ms; aim 100 ms)")
print(f"  baseline, an empty cell through the kernel: {ms(empty):.1f} ms")
print(f"  baseline, pointcalc example 2 -o x.svg as a process: {ms(procs):.1f} ms")
