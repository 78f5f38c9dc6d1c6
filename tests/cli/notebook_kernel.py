"""Drive the pointcalc Jupyter kernel through jupyter_client (tests/cli/test_notebook.sh).

Run with JUPYTER_PATH naming the folder that holds kernels/pointcalc. Each check prints
"ok NAME" or "FAIL NAME: why"; the exit status is the number of failures."""
import base64
import sys
import time

from jupyter_client.manager import start_new_kernel

failures = 0


def check(name, cond, why=""):
    global failures
    if cond:
        print("ok", name)
    else:
        failures += 1
        print("FAIL", name + ":", why)


km, kc = start_new_kernel(kernel_name="pointcalc", startup_timeout=60)


def reply_to(msg_id, timeout):
    while True:
        m = kc.get_shell_msg(timeout=timeout)
        if m["parent_header"].get("msg_id") == msg_id:
            return m["content"]


def run(code, timeout=30):
    """The reply and the iopub messages (type, content) of one cell.  stop_on_error=False: the
    cells here are independent (with True, ipykernel aborts what arrives just after an error)."""
    msg_id = kc.execute(code, stop_on_error=False)
    outs = []
    while True:
        m = kc.get_iopub_msg(timeout=timeout)
        if m["parent_header"].get("msg_id") != msg_id:
            continue
        if m["msg_type"] == "status" and m["content"]["execution_state"] == "idle":
            break
        if m["msg_type"] in ("stream", "display_data", "execute_result", "error"):
            outs.append((m["msg_type"], m["content"]))
    return reply_to(msg_id, timeout), outs


def kinds(outs):
    return [t for t, _ in outs]


# a cell's output, and state kept between cells
reply, outs = run("x = 6 * 7\nprint('x is', x)")
check("a cell runs", reply["status"] == "ok", reply)
check("print reaches stdout", ("stream", {"name": "stdout", "text": "x is\t42\n"}) in outs, outs)
check("a cell that does not draw shows no figure", "display_data" not in kinds(outs), outs)
reply, outs = run("x + 1")
check("globals live on; an expression shows its value",
      [c["data"]["text/plain"] for t, c in outs if t == "execute_result"] == ["43"], outs)

# a drawing cell returns its figure as SVG
t0 = time.time()
reply, outs = run("screen(12)\ncircle(P(320, 240), 100, 14)\nline(P(0, 0), P(639, 479), 9)")
figs = [c["data"] for t, c in outs if t == "display_data"]
check("a drawing cell returns image/svg+xml", len(figs) == 1 and "image/svg+xml" in figs[0], outs)
svg = figs[0]["image/svg+xml"] if figs else ""
check("the SVG is the canvas", svg.startswith("<?xml") or svg.startswith("<svg"), svg[:80])
check("the SVG holds the circle's colour (yellow, 14)", "#ffff55" in svg.lower(), svg[:400])
reply, outs = run("circle(P(320, 240), 100, 14)")
check("a cell that draws the same again still shows it", "display_data" in kinds(outs), outs)
reply, outs = run("--%png\ncircle(P(100, 100), 50, 12)")
figs = [c["data"] for t, c in outs if t == "display_data"]
check("--%png gives image/png", len(figs) == 1 and "image/png" in figs[0], outs)
if figs and "image/png" in figs[0]:
    png = base64.b64decode(figs[0]["image/png"])
    check("the PNG is a PNG of 640x480", png[:8] == b"\x89PNG\r\n\x1a\n" and
          int.from_bytes(png[16:20], "big") == 640 and int.from_bytes(png[20:24], "big") == 480,
          png[:24])

# errors come back with the cell's line
reply, outs = run("local a = 1\n\nlocal b = a + nil")
check("an error cell fails", reply["status"] == "error", reply)
check("the error names the cell's line", reply.get("evalue", "").startswith("cell:3: "), reply)
check("the error is published", "error" in kinds(outs), outs)
reply, outs = run("circle(P(1, 2), -5)")
check("a native's message names the call", "circle" in reply.get("evalue", ""), reply)
reply, outs = run("x")
check("the state survives an error", [c["data"]["text/plain"] for t, c in outs if t == "execute_result"] == ["42"], outs)

# completion and inspection from the registry
m = kc.complete("ler", 3, reply=True, timeout=10)["content"]
check("completion of ler", "lerp" in m["matches"] and m["cursor_start"] == 0, m)
m = kc.complete("y = map.sc", 10, reply=True, timeout=10)["content"]
check("completion of map.sc", "map.scale" in m["matches"] and m["cursor_start"] == 4, m)
m = kc.inspect("lerp(A, B, t)", 2, reply=True, timeout=10)["content"]
check("inspection shows the registry's signature", m["found"] and
      m["data"]["text/plain"].startswith("lerp(A, B, t) -> value"), m)
reply, outs = run(":help lerp")
check(":help in a cell", any(t == "stream" and "lerp(A, B, t)" in c["text"] for t, c in outs), outs)

# an interrupt stops a runaway cell, and the notebook goes on
msg_id = kc.execute("while true do end", stop_on_error=False)
time.sleep(1.0)
km.interrupt_kernel()
r = reply_to(msg_id, 15)
check("an interrupt stops while true do end", r["status"] == "error" and "interrupted" in r.get("evalue", ""), r)
check("the interrupt stopped the cell, not the process", "restarted" not in r.get("evalue", ""), r)
reply, outs = run("x")
check("the state survives an interrupt", [c["data"]["text/plain"] for t, c in outs if t == "execute_result"] == ["42"], (reply, outs))

kc.stop_channels()
km.shutdown_kernel(now=True)
sys.exit(failures)
