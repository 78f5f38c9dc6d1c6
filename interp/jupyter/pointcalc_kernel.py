"""The pointcalc Jupyter kernel (docs/notebook.md).

One `pointcalc kernel.lua` process per notebook holds the Lua state; this wrapper speaks the
Jupyter protocol through ipykernel and forwards each cell to it (see kernel.lua for the
framing). A cell that drew shows its figure inline: SVG by default, PNG after a first line
`--%png`, the print look (PDF, where pointcalc writes PDF) after `--%print`. Errors come back as
`cell:LINE: message`; completion and inspection (Shift-Tab) come from the help registry; an
interrupt stops a runaway cell (and restarts the process if the cell does not stop).
"""
import base64
import os
import re
import shutil
import subprocess
import sys
import select
import tempfile
import time

from ipykernel.kernelbase import Kernel

HERE = os.path.dirname(os.path.abspath(__file__))


def find_pointcalc():
    """$POINTCALC, else the program of this kernel's own prefix
    (PREFIX/share/jupyter/kernels/pointcalc -> PREFIX/bin), else the one on PATH."""
    env = os.environ.get("POINTCALC")
    if env:
        return env
    mine = os.path.normpath(os.path.join(HERE, "..", "..", "..", "..", "bin", "pointcalc"))
    if os.access(mine, os.X_OK):
        return mine
    return shutil.which("pointcalc") or "pointcalc"


class PointcalcKernel(Kernel):
    implementation = "pointcalc"
    implementation_version = "0.1.0"
    language = "lua"
    language_version = "5.4"
    language_info = {
        "name": "lua",
        "mimetype": "text/x-lua",
        "file_extension": ".lua",
        "codemirror_mode": "lua",
        "pygments_lexer": "lua",
    }
    banner = "pointcalc: point calculus and QBasic-style drawing in Lua 5.4"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.tmp = tempfile.mkdtemp(prefix="pointcalc-kernel-")
        self.stop_file = os.path.join(self.tmp, "stop")
        self.proc = None
        self.start_pointcalc()

    # --- the pointcalc process -----------------------------------------------------------
    def start_pointcalc(self):
        self.out_path = os.path.join(self.tmp, "stdout")
        self.err_path = os.path.join(self.tmp, "stderr")
        self.out = open(self.out_path, "wb+")
        self.err = open(self.err_path, "wb+")
        req_r, req_w = os.pipe()
        rep_r, rep_w = os.pipe()
        env = dict(os.environ, PC_KERNEL_STOP=self.stop_file, PC_KERNEL_TMP=self.tmp,
                   PC_KERNEL_REQUESTS=str(req_r), PC_KERNEL_REPLIES=str(rep_w))
        self.proc = subprocess.Popen(
            [find_pointcalc(), os.path.join(HERE, "kernel.lua")],
            stdin=subprocess.DEVNULL, stdout=self.out, stderr=self.err, env=env,
            pass_fds=(rep_w, req_r), cwd=os.getcwd(),
            start_new_session=True)   # Jupyter's SIGINT to the kernel's group is not for it
        os.close(req_r)
        os.close(rep_w)
        self.req = os.fdopen(req_w, "wb")
        self.rep = os.fdopen(rep_r, "rb")
        self.out_pos = self.err_pos = 0

    def restart(self):
        try:
            self.proc.kill()
            self.proc.wait(5)
        except Exception:
            pass
        for f in (self.req, self.rep, self.out, self.err):
            try:
                f.close()
            except Exception:
                pass
        self.start_pointcalc()

    def request(self, verb, text, arg=""):
        data = text.encode("utf-8")
        self.req.write(b"%s %d %s\n" % (verb.encode(), len(data), arg.encode()))
        self.req.write(data)
        self.req.flush()

    def frames(self):
        """Yield (tag, bytes) until "done"; None when the process died."""
        while True:
            head = self.rep.readline()
            if not head:
                yield None, None
                return
            tag, n = head.decode().split()
            body = self.rep.read(int(n))
            if tag == "done":
                return
            yield tag, body

    def streams(self):
        """What the cell wrote to standard output and error, as stream messages."""
        for f, name, attr in ((self.out, "stdout", "out_pos"), (self.err, "stderr", "err_pos")):
            f.flush()
            f.seek(getattr(self, attr))
            data = f.read()
            setattr(self, attr, getattr(self, attr) + len(data))
            f.seek(0, 2)
            if data and not self.silent_now:
                self.send_response(self.iopub_socket, "stream",
                                   {"name": name, "text": data.decode("utf-8", "replace")})

    # --- the protocol --------------------------------------------------------------------
    def do_execute(self, code, silent, store_history=True, user_expressions=None,
                   allow_stdin=False, *, cell_id=None):
        self.silent_now = silent
        first = code.split("\n", 1)[0].strip()
        look = {"--%png": "png", "--%print": "print", "--%svg": "svg"}.get(first, "svg")
        if os.path.exists(self.stop_file):
            os.remove(self.stop_file)
        error = None
        try:
            self.request("exec", code, look)
            for tag, body in self.frames():
                if tag is None:
                    error = "the pointcalc process ended; it has been restarted (the notebook's state is lost)"
                    self.restart()
                    break
                self.dispatch(tag, body, silent)
                if tag == "error":
                    error = body.decode("utf-8", "replace")
        except KeyboardInterrupt:
            error = self.interrupt()
        self.streams()
        if error is not None:
            name, _, _ = error.partition("\n")
            m = re.match(r"cell:(\d+): ", error)
            if not silent:
                self.send_response(self.iopub_socket, "error", {
                    "ename": "error", "evalue": name, "traceback": error.split("\n")})
            return {"status": "error", "execution_count": self.execution_count,
                    "ename": "error", "evalue": name, "traceback": error.split("\n"),
                    "line": int(m.group(1)) if m else None}
        return {"status": "ok", "execution_count": self.execution_count,
                "payload": [], "user_expressions": {}}

    def dispatch(self, tag, body, silent):
        if silent:
            return
        if tag == "result":
            self.send_response(self.iopub_socket, "execute_result", {
                "execution_count": self.execution_count,
                "data": {"text/plain": body.decode("utf-8", "replace")}, "metadata": {}})
        elif tag == "stderr":
            self.streams()
            self.send_response(self.iopub_socket, "stream",
                               {"name": "stderr", "text": body.decode("utf-8", "replace")})
        elif tag == "image/svg+xml":
            self.streams()
            self.send_response(self.iopub_socket, "display_data", {
                "data": {"image/svg+xml": body.decode("utf-8"), "text/plain": "<pointcalc figure>"},
                "metadata": {}})
        elif tag in ("image/png", "application/pdf"):
            self.streams()
            data = {tag: base64.b64encode(body).decode("ascii"), "text/plain": "<pointcalc figure>"}
            self.send_response(self.iopub_socket, "display_data", {"data": data, "metadata": {}})

    def interrupt(self):
        """Ask the cell to stop (kernel.lua's hook); a cell stuck in C is stopped by a restart."""
        open(self.stop_file, "w").close()
        # wait up to 3 s for the cell's reply to begin; once it does, the rest follows at once
        ready, _, _ = select.select([self.rep], [], [], 3.0)
        if ready:
            error = "interrupted"
            for tag, body in self.frames():
                if tag is None:
                    break
                if tag == "error":
                    error = body.decode("utf-8", "replace")
            else:
                return error
        self.restart()
        return "interrupted: the cell did not stop, so pointcalc was restarted (the notebook's state is lost)"

    def do_complete(self, code, cursor_pos):
        pos = len(code[:cursor_pos].encode("utf-8"))
        self.request("complete", code, str(pos))
        start, matches = cursor_pos, []
        for tag, body in self.frames():
            if tag == "start":
                start = len(code.encode("utf-8")[:int(body)].decode("utf-8", "replace"))
            elif tag == "matches":
                matches = [m for m in body.decode("utf-8").split("\n") if m]
        return {"status": "ok", "matches": matches, "cursor_start": start,
                "cursor_end": cursor_pos, "metadata": {}}

    def do_inspect(self, code, cursor_pos, detail_level=0, omit_sections=()):
        pos = len(code[:cursor_pos].encode("utf-8"))
        self.request("inspect", code, str(pos))
        text = None
        for tag, body in self.frames():
            if tag == "inspect":
                text = body.decode("utf-8")
        return {"status": "ok", "found": text is not None,
                "data": {"text/plain": text} if text else {}, "metadata": {}}

    def do_shutdown(self, restart):
        try:
            self.proc.kill()
        except Exception:
            pass
        shutil.rmtree(self.tmp, ignore_errors=True)
        return {"status": "ok", "restart": restart}


if __name__ == "__main__":
    from ipykernel.kernelapp import IPKernelApp
    IPKernelApp.launch_instance(kernel_class=PointcalcKernel)
