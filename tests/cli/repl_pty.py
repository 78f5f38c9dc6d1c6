"""The REPL driven through a pseudo-terminal, as a user types at it (run by test_repl.sh).

Each check types lines (Tab and arrow keys included), waits for the next prompt and reads what
the REPL printed.  Environment: POINTCALC (the binary); the working directory is a scratch
folder, HOME is set to a folder inside it.
"""
import os
import pty
import re
import select
import signal
import struct
import sys
import time

POINTCALC = os.environ["POINTCALC"]
TIMEOUT = 15
ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]|\x1b[()][A-Za-z0-9]|\x1b[=>]|\r|\x07")

failures = 0
checks = 0


def fail(what, detail):
    global failures
    failures += 1
    print(f"FAIL: {what}: {detail}", file=sys.stderr)


def expect(cond, what, detail=""):
    global checks
    checks += 1
    if not cond:
        fail(what, detail)


class Ended(Exception):
    """The REPL exited when it should not have: nothing after that can be checked."""


class Repl:
    """A pointcalc process on a pseudo-terminal of cols x rows."""

    def __init__(self, args=(), env=None, cols=80, rows=24):
        self.env = dict(os.environ)
        self.env.update({"HOME": os.path.abspath("home"), "TERM": "xterm", "NO_COLOR": "1"})
        self.env.pop("COLORTERM", None)
        self.env.update(env or {})
        self.env = {k: v for k, v in self.env.items() if v is not None}
        pid, fd = pty.fork()
        if pid == 0:
            import fcntl
            import termios
            fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
            os.execve(POINTCALC, [POINTCALC, *args], self.env)
        self.pid, self.fd = pid, fd
        self.raw = b""        # everything read so far
        self.mark = 0         # where the current answer starts
        self.status = None
        self.wait_for(rb"\n> $|^> $", "the first prompt")

    def read_some(self, timeout):
        r, _, _ = select.select([self.fd], [], [], timeout)
        if not r:
            return False
        try:
            data = os.read(self.fd, 65536)
        except OSError:
            data = b""
        if not data:
            raise EOFError
        self.raw += data
        return True

    def wait_for(self, pattern, what):
        """Read until pattern (bytes regex) matches the output since the mark."""
        deadline = time.time() + TIMEOUT
        rx = re.compile(pattern, re.S)
        while not rx.search(self.raw[self.mark:]):
            left = deadline - time.time()
            try:
                if left <= 0 or not self.read_some(left):
                    fail(what, "timed out; output so far: %r" % self.raw[self.mark:][-600:])
                    return None
            except EOFError:
                raise Ended("%s: the REPL ended; output: %r" % (what, self.raw[-800:]))
        return rx.search(self.raw[self.mark:])

    def type(self, keys):
        self.wait_editing()
        os.write(self.fd, keys.encode())

    def wait_editing(self):
        """Wait until the line editor has the terminal (canonical mode off).  Keys typed before
        would be echoed twice: once by the terminal, once by the editor."""
        import termios
        deadline = time.time() + 2
        while time.time() < deadline:
            try:
                if not termios.tcgetattr(self.fd)[3] & termios.ICANON:
                    return
            except termios.error:
                return
            time.sleep(0.01)

    def answer(self, keys, prompt=rb"\n> $", what=None):
        """Type keys (ending in Enter), wait for the prompt, return the text in between
        (escape sequences and the echoed input line removed)."""
        self.mark = len(self.raw)
        self.type(keys)
        if self.wait_for(prompt, what or repr(keys)) is None:
            return ""
        text = ANSI.sub("", self.raw[self.mark:].decode("utf-8", "replace"))
        lines = text.split("\n")
        return "\n".join(lines[1:-1])   # drop the echoed input and the new prompt

    def line(self, text, prompt=rb"\n> $"):
        return self.answer(text + "\r", prompt)

    def finish(self, keys):
        """Type keys that should end the session; return the exit status."""
        self.mark = len(self.raw)
        self.type(keys)
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self.status = os.waitstatus_to_exitcode(status)
                os.close(self.fd)
                return self.status
            try:
                self.read_some(0.1)
            except EOFError:
                time.sleep(0.05)
        fail("session end", "the REPL did not exit; output: %r" % self.raw[self.mark:][-300:])
        os.kill(self.pid, signal.SIGKILL)
        os.waitpid(self.pid, 0)
        os.close(self.fd)
        return None


def ppm_pixels(path):
    """(width, height, rgb bytes) of a binary PPM written by pointcalc."""
    data = open(path, "rb").read()
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    w, h = int(m.group(1)), int(m.group(2))
    return w, h, data[m.end():]


def braille_from_ppm(path, cols, scale):
    """The braille lines the REPL should print for a canvas, computed independently: a dot is
    set when any pixel of its scale x scale block is not black."""
    w, h, px = ppm_pixels(path)
    rows = -(-h // int(4 * scale))
    bits = [[0] * cols for _ in range(rows)]
    dotbit = {(0, 0): 0x01, (0, 1): 0x02, (0, 2): 0x04, (1, 0): 0x08, (1, 1): 0x10,
              (1, 2): 0x20, (0, 3): 0x40, (1, 3): 0x80}
    for y in range(h):
        for x in range(w):
            i = 3 * (y * w + x)
            if px[i] or px[i + 1] or px[i + 2]:
                dx, dy = int(x // scale), int(y // scale)
                bits[dy // 4][dx // 2] |= dotbit[(dx % 2, dy % 4)]
    return ["".join(" " if b == 0 else chr(0x2800 + b) for b in row) for row in bits]


def main():
    os.makedirs("home", exist_ok=True)

    # ---- a session: statements, values, errors, completion, help, the canvas --------------
    r = Repl()
    expect(r.line("A = P(1, 2)") == "", "an assignment prints nothing")
    out = r.line("A")
    expect(out == "P(1, 2)", "a point prints as P(1, 2)", repr(out))
    out = r.line("V(0, 1)")
    expect(out == "V(0, 1)", "a vector prints as V(0, 1)", repr(out))
    out = r.line("lerp(P(0, 0), P(4, 2), 0.5), 1 + 1")
    expect(out == "P(2, 1)\t2", "several values, tab-separated", repr(out))
    out = r.line("{1, 2, 3}")
    expect(out == "table: 3 items {1, 2, 3}", "a table prints as a summary", repr(out))
    r.line("big = {} for i = 1, 50000 do big[i] = i * i end")
    out = r.line("big")
    expect(out == "table: 50000 items {1, 4, 9, 16, 25, 36, 49, 64, ...}",
           "a huge table is summarised, not dumped", repr(out))
    out = r.line("affine.identity(2)")
    expect(out.startswith("affine map"), "a map prints as a summary", repr(out))

    # a multi-line function: the continuation prompt, then a call
    out = r.line("function sq(x)", prompt=rb"\n>> $")
    expect(out == "", "an unfinished chunk asks for more", repr(out))
    r.line("  return x * x", prompt=rb"\n>> $")
    out = r.line("end")
    expect(out == "", "the function is defined", repr(out))
    out = r.line("sq(7)")
    expect(out == "49", "the multi-line function works", repr(out))

    # errors are reported and the session goes on
    out = r.line("error('boom')")
    expect(out == "stdin:1: boom", "a runtime error", repr(out))
    out = r.line("sq(nil)")
    expect("attempt to perform arithmetic on a nil value" in out and "in function 'sq'" in out,
           "an error inside a function shows where", repr(out))
    out = r.line("x = = 1")
    expect(out.startswith("stdin:1:") and "near '='" in out, "a syntax error", repr(out))
    out = r.line("circle(1, 2)")
    expect(out == "stdin:1: circle: argument #3 (radius) must be a non-negative number, got nil",
           "an argument error, without a useless traceback", repr(out))
    out = r.line("circel(320, 240, 10)")
    expect(out == "stdin:1: attempt to call a nil value (global 'circel')\n(did you mean 'circle'?)",
           "a misspelt name gets a suggestion", repr(out))
    out = r.line("1 + 1")
    expect(out == "2", "the session goes on after errors", repr(out))

    # Ctrl-C interrupts a running statement, and drops a half-typed line at the prompt
    r.mark = len(r.raw)
    r.type("while true do end\r")
    found = None
    for _ in range(TIMEOUT):   # Ctrl-C once a second until the loop has been interrupted
        time.sleep(0.3)
        os.write(r.fd, b"\x03")
        deadline = time.time() + 1
        while time.time() < deadline and not found:
            found = re.search(rb"interrupted\r?\n> $", r.raw[r.mark:])
            r.read_some(0.1)
        if found:
            break
    expect(found is not None, "Ctrl-C interrupts a running statement", repr(r.raw[r.mark:][-200:]))
    out = r.answer("abc\x03")
    expect(out == "" or out == "^C", "Ctrl-C drops the line being typed", repr(out))
    out = r.line("2 + 2")
    expect(out == "4", "the session goes on after Ctrl-C", repr(out))

    # Tab completion: a global name, a field after '.', a method after ':'
    out = r.answer("ler\t\r")
    expect(out.startswith("function lerp(A, B, t)"), "Tab completes a global name", repr(out))
    out = r.answer("string.up\t('abc')\r")
    expect(out == "ABC", "Tab completes a field after '.'", repr(out))
    out = r.answer("A:di\tP(4, 6))\r")
    expect(out == "5.0", "Tab completes a point's method after ':'", repr(out))
    out = r.answer("A.\t\t\x15\r")   # two Tabs list the fields and methods; Ctrl-U drops the line
    expect("A.x" in out and "A.unit" in out and "A.z" not in out,
           "Tab lists a point's fields and methods", repr(out))

    # :help
    out = r.line(":help lerp")
    expect(out.startswith("lerp(A, B, t) -> value\n") and "t = 0 gives A" in out,
           ":help NAME prints the signature and the description", repr(out))
    out = r.line(":help")
    expect("Commands" in out and ":show [COLUMNS]" in out and "Drawing" in out and "pset" in out,
           ":help lists the commands and the API by area", repr(out[:300]))
    out = r.line("?")
    expect(out.startswith("Commands"), "a lone '?' is :help", repr(out[:80]))
    out = r.line(":nonsense")
    expect("unknown command ':nonsense'" in out, "an unknown command", repr(out))

    # drawing, :save, :show (exact braille cells against the saved pixels)
    r.line("circle(320, 240, 100, 14)")
    out = r.line(":save c.ppm")
    expect(out == "wrote c.ppm" and os.path.exists("c.ppm"), ":save writes the file", repr(out))
    out = r.line(":save c.png")
    expect(open("c.png", "rb").read(8) == b"\x89PNG\r\n\x1a\n", ":save writes a PNG", repr(out))
    out = r.line(":save c2.png blue")
    expect(out == "cannot write 'c2.png': the theme must be paper or screen, got 'blue'"
           and not os.path.exists("c2.png"), ":save with an unknown theme", repr(out))
    out = r.line(":show 40")
    lines = out.split("\n")
    want = braille_from_ppm("c.ppm", 40, 8.0)
    expect(len(lines) == len(want) + 3, ":show 40: frame, 15 rows, caption", repr(out))
    if len(lines) == len(want) + 3:
        expect(lines[0] == "\u250c" + "\u2500" * 40 + "\u2510", ":show top frame", repr(lines[0]))
        got = [l[1:-1] for l in lines[1:-2]]
        expect(got == want, ":show cells are the circle's pixels",
               "\n" + "\n".join(got) + "\nwant\n" + "\n".join(want))
        # the top of the circle (320, 140) is dot (40, 17): cell row 4, column 20; the centre
        # (320, 240) is dot (40, 30): cell row 7, column 20, and is empty
        expect(got[4][20] != " " and got[7][20] == " ", ":show the circle, not its inside")
        expect(lines[-1].strip() == "640x480, 8 pixels per dot", ":show caption", repr(lines[-1]))
    out = r.line(":show")
    lines = out.split("\n")
    # fitted to 80x24: at most 78 x 20 cells, 6 pixels per dot: 54 x 20
    expect(len(lines) == 23 and len(lines[1]) == 56, ":show fits the terminal",
           "%d lines, width %d" % (len(lines), len(lines[1]) if len(lines) > 1 else -1))

    # :load runs a script in the session; :clear erases the drawing but keeps the settings
    with open("tri.lua", "w") as f:
        f.write("T = {P(100, 100), P(200, 100), P(150, 50)}\n"
                "for i = 1, 3 do line(T[i], T[i % 3 + 1], 12) end\n"
                "print('triangle drawn')\n")
    out = r.line(":load tri.lua")
    expect(out == "triangle drawn", ":load runs the script", repr(out))
    out = r.line("#T, point(150, 100)")
    expect(out == "3\t12", "the script's globals and drawing are in the session", repr(out))
    with open("ring.bas", "w") as f:
        f.write("' a QBasic program\r\nSCREEN 12\r\nCIRCLE (500, 400), 30, 10\r\n")
    out = r.line(":load ring.bas")
    expect(out == "", ":load runs a QBasic program", repr(out))
    out = r.line("point(530, 400)")
    expect(out == "10", "the QBasic program drew in the session", repr(out))
    with open("bad.lua", "w") as f:
        f.write("local function inner() error('bad script') end\ninner()\n")
    out = r.line(":load bad.lua")
    expect(out.startswith("bad.lua:1: bad script\nstack traceback:") and "bad.lua:2: in main chunk" in out
           and "repl.lua" not in out, ":load shows the script's error and its lines only", repr(out))
    # Tab completes file names after :load and :save; a name with a blank gets a quote, which
    # the command reads as one argument, also when the user typed the quote
    out = r.answer(":load tr\t\r")
    expect(out == "triangle drawn", "Tab completes a file name after :load", repr(out))
    os.makedirs("my pics", exist_ok=True)
    out = r.answer(":save my\tring.ppm\r")
    expect(out == "wrote my pics/ring.ppm" and os.path.exists("my pics/ring.ppm"),
           "Tab quotes a folder name with a blank", repr(out))
    with open("my pics/tri 2.lua", "w") as f:
        f.write("print('second triangle')\n")
    out = r.answer(':load "my p\ttri\t\r')
    expect(out == "second triangle", "Tab completes inside a quoted file name", repr(out))
    out = r.line(":load missing.lua")
    expect("cannot open 'missing.lua'" in out, ":load of a missing file", repr(out))
    r.line("window(0, 0, 64, 48)")
    out = r.line(":clear")
    expect(out == "", ":clear is quiet", repr(out))
    r.line("pset(32, 24, 4)")
    r.line(":save cleared.ppm")
    w, h, px = ppm_pixels("cleared.ppm")
    ink = [i // 3 for i in range(0, len(px), 3) if px[i] or px[i + 1] or px[i + 2]]
    # the triangle and the circle are gone; the window survived :clear: world (32, 24) is the
    # centre of the screen
    expect(len(ink) == 1 and ink[0] in (240 * 640 + 320, 239 * 640 + 320, 240 * 640 + 319,
                                          239 * 640 + 319),
           ":clear erases the drawing and keeps the window", repr(ink[:5]))

    # the last entry before quitting, for the history check
    r.line("print('hist' .. 'mark', 6 * 7)")
    status = r.finish(":quit\r")
    expect(status == 0, ":quit exits with status 0", repr(status))

    # ---- history persists in $HOME ------------------------------------------------------
    hist = os.path.join("home", ".pointcalc_history")
    expect(os.path.exists(hist), "the history file is in $HOME")
    if os.path.exists(hist):
        text = open(hist, "rb").read()
        expect(b"mark" in text and b"sq" in text, "the history file has the session's lines",
               repr(text[-200:]))
    r = Repl()
    out = r.answer("\x1b[A\x1b[A\r")   # Up twice: past ":quit" to the print
    expect(out == "histmark\t42", "the history of the last session is recalled", repr(out))
    status = r.finish("\x04")          # Ctrl-D
    expect(status == 0, "Ctrl-D exits with status 0", repr(status))

    # ---- colour in :show when the terminal has it ----------------------------------------
    r = Repl(env={"NO_COLOR": None, "TERM": "xterm-256color"})
    r.line("circle(320, 240, 100, 14)")
    r.mark = len(r.raw)
    r.type(":show\r")
    r.wait_for(rb"per dot.*\n> $", ":show in colour")
    raw = r.raw[r.mark:]
    expect(b"\x1b[38;5;227m" in raw, ":show colours yellow ink (colour 14) on a 256-colour terminal",
           repr(raw[:200]))
    r.finish(":q\r")

    # ---- --watch FILE rewrites the file after statements that draw -----------------------
    r = Repl(args=["--watch", "w.ppm"])
    expect(os.path.exists("w.ppm"), "--watch writes the file at once")
    first = os.stat("w.ppm").st_ino if os.path.exists("w.ppm") else None
    r.line("pset(5, 5, 14)")
    w, h, px = ppm_pixels("w.ppm")
    i = 3 * (5 * w + 5)
    expect(px[i:i + 3] == b"\xff\xff\x55", "--watch: the file shows the new pixel", repr(px[i:i + 3]))
    second = os.stat("w.ppm").st_ino
    expect(second != first, "--watch rewrote the file (atomically: a new inode)")
    r.line("x = 42")
    expect(os.stat("w.ppm").st_ino == second, "--watch: no rewrite when nothing was drawn")
    r.line("line(0, 0, 10, 0, 2)")
    w, h, px = ppm_pixels("w.ppm")
    expect(px[3 * 10:3 * 10 + 3] == b"\x00\xaa\x00", "--watch after a line", repr(px[30:33]))
    r.line(":clear")
    w, h, px = ppm_pixels("w.ppm")
    expect(not any(px), "--watch after :clear: a blank picture")
    r.line(":watch w.svg")
    r.line("circle(50, 50, 20)")
    svg = open("w.svg").read() if os.path.exists("w.svg") else ""
    expect("<svg" in svg and "circle" in svg, ":watch switches to another file", svg[:200])
    r.finish(":q\r")

    # ---- -i after a script: its globals are there ---------------------------------------
    with open("setup.lua", "w") as f:
        f.write("O = P(320, 240)\n")
    r = Repl(args=["-i", "setup.lua"])
    out = r.line("O + V(1, 1)")
    expect(out == "P(321, 241)", "-i: the script's globals", repr(out))
    r.finish("\x04")

    print(f"{checks} checks, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Ended as e:
        fail("session", str(e))
        print(f"{checks} checks, {failures} failed (stopped early)")
        sys.exit(1)
