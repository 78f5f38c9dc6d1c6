# Hardening, part two (issue 26, docs/safety.md): each defect the second reliability probe found,
# reproduced; every check here failed before its fix.
. "$(dirname "$0")/lib.sh"
sanitized() { [ "${PC_SANITIZE:-0}" = 1 ]; }   # AddressSanitizer has its own allocator

# measure CMD...: runs it like run, and puts its peak resident size (kB) in $peak
measure() {
    set -- $(python3 -c 'import resource, subprocess, sys
r = subprocess.run(sys.argv[1:], stdout=open("out.txt", "w"), stderr=open("err.txt", "w"))
print(r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' "$@")
    rc=$1; peak=$2
}
expect_peak_below() {  # expect_peak_below MB DESCRIPTION
    checks=$((checks + 1))
    sanitized || [ "$peak" -lt $(($1 * 1024)) ] || fail "$2: peak $((peak / 1024)) MB, want under $1 MB"
}

# --- 1. a number as a file name is checked as the name it becomes ---
mkdir ok && printf 'private' > 2024 && printf 'x' > 1.5
for call in 'io.open(2024)' 'io.lines(2024)' 'io.input(2024)' 'io.output(1.5)' 'os.remove(2024)' \
            'os.rename(2024, "ok/got")' 'dofile(2024)' 'loadfile(2024)' 'io.open(1/0, "w")' \
            'io.open(-(0/0), "w")' 'io.open(1e20, "a")'; do
    run "$POINTCALC" --safe --allow ok -e "$call"
    expect_rc 1 "--safe: $call"
    expect_in err.txt "(file name) must be a file under an allowed folder (" "--safe: $call refused"
done
expect_eq "$(cat 2024)" "private" "the number-named file is untouched"
expect_no_file inf "no file 'inf' created"
expect_no_file 1e+20 "no file '1e+20' created"
expect_no_file ok/got "nothing renamed"
run "$POINTCALC" --safe --allow ok -e 'print(io.open(2024))'
expect_in err.txt "got '2024'" "the message shows the converted name"
# inside the allowed folder a number name works as Lua has it
run "$POINTCALC" --safe --allow . -e 'local f = io.open(7, "w") f:write("seven") f:close() print(io.open(7):read("a")) print(os.remove(7))'
expect_rc 0 "--safe --allow .: a number name inside"
expect_eq "$(cat out.txt)" "$(printf 'seven\ntrue')" "--safe: number name read back and removed"

# --- 6. no check-then-open race: a link swapped in an allowed folder never reads outside ---
printf 'SECRET' > secret.txt && printf 'inside' > ok/inside.txt
python3 -c 'import os, time
end = time.time() + 30
while time.time() < end and os.path.exists("ok"):
    for t in ("inside.txt", "../secret.txt"):
        os.symlink(t, "ok/sw.tmp"); os.replace("ok/sw.tmp", "ok/sw")' 2>/dev/null & swapper=$!
n=0; while [ ! -L ok/sw ] && [ $n -lt 100 ]; do sleep 0.05; n=$((n + 1)); done
run "$POINTCALC" --safe --allow ok -e '
-- a loaded machine may starve the swapper: try until both states were met (or 20 s), at least 4000 times
local outside, inside, refused, i, stop = 0, 0, 0, 0, os.time() + 20
while i < 4000 or ((inside == 0 or refused == 0) and os.time() < stop) do
  i = i + 1
  local ok, f = pcall(io.open, "ok/sw")
  if not ok then refused = refused + 1
  elseif f then
    local s = f:read("a") f:close()
    if s == "SECRET" then outside = outside + 1 elseif s == "inside" then inside = inside + 1 end
  end
end
print(outside, inside > 0, refused > 0)'
kill $swapper 2>/dev/null; wait $swapper 2>/dev/null
expect_rc 0 "link race: ran"
expect_eq "$(cat out.txt)" "$(printf '0\ttrue\ttrue')" "link race: 0 outside reads, inside reads and refusals both seen"

# --- 8. the smaller holes ---
run "$POINTCALC" --safe -e 'io.tmpfile()'; expect_rc 1 "--safe: io.tmpfile"
expect_in err.txt "io.tmpfile is not available in safe mode" "--safe: io.tmpfile refused"
run "$POINTCALC" --safe -e 'print(package.searchpath("passwd", "/etc/?"))'; expect_rc 1 "--safe: package.searchpath"
expect_in err.txt "package.searchpath is not available in safe mode" "--safe: package.searchpath refused"
ln secret.txt ok/hard.txt
run "$POINTCALC" --safe --allow ok -e 'print(io.open("ok/hard.txt"):read("a"))'; expect_rc 1 "--safe: a hard link"
expect_in err.txt "must be a file without other hard links" "--safe: a hard link refused"
run "$POINTCALC" --safe --allow ok -e 'io.open("ok/hard.txt", "w")'; expect_rc 1 "--safe: truncating a hard link"
expect_eq "$(cat secret.txt)" "SECRET" "the hard-linked file is untouched"
run "$POINTCALC" --safe --allow ok --allow-hardlinks -e 'print(io.open("ok/hard.txt"):read("a"))'
expect_rc 0 "--allow-hardlinks"
expect_eq "$(cat out.txt)" "SECRET" "--allow-hardlinks: the user's choice"
rm ok/hard.txt
# io.lines with formats, and closing at the end, as Lua's own
printf '1 2\n3 4\n' > ok/n.txt
run "$POINTCALC" --safe --allow ok -e 'local s = 0 for a, b in io.lines("ok/n.txt", "n", "n") do s = s + a * b end print(s)'
expect_eq "$(cat out.txt)" "14" "--safe: io.lines with formats"
# a kill during a save leaves no temporary file (the file is unnamed until renamed into place)
mkdir k
printf 'screen{width = 2000, height = 2000}\nfor i = 0, 1999, 3 do line(0, i, 1999, 1999 - i, i %% 16) end\nwhile true do save(arg[1] .. "/x.png") end\n' > saveloop.lua
for delay in 0.3 0.5 0.7 0.9; do
    "$POINTCALC" saveloop.lua k 2>/dev/null & pid=$!
    sleep $delay; kill -9 $pid; wait $pid 2>/dev/null
done
expect_eq "$(ls -A k | grep -c '^\.')" "0" "kill -9 during saves: no temporary file"

# --- 3. memory limits hold inside native calls (peak resident size within the limit) ---
for case in 'screen{width = 16384, height = 16384, colors = 256} line(0, 0, 16000, 16000, 3, "bf")' \
            'screen{width = 16384, height = 16384, colors = 256} circle(8000, 8000, 7000, 3) paint(8000, 8000, 5, 3)' \
            'local s = string.rep("x", 6e7) for i = 1, 4 do label(s, P(i, i)) end' \
            'for i = 1, 1e7 do line(0, 0, i % 640, 479, 3) end'; do
    measure "$POINTCALC" --max-memory 100 -e "$case" -o big.png
    expect_rc 1 "--max-memory 100: $case"
    expect_in err.txt "memory limit of 100 MB" "--max-memory 100: $case: the message"
    expect_in err.txt "(command line):1:" "--max-memory 100: $case: the line"
    expect_peak_below 112 "--max-memory 100: $case"
    expect_no_file big.png "--max-memory 100: no picture"
done
sanitized || expect_in err.txt "(the memory limit of 100 MB was reached: a request of" "the refusal is explained"
# --safe alone has a limit (1024 MB)
measure "$POINTCALC" --safe -e 'local s = string.rep("x", 2e9)'
expect_rc 1 "--safe: default memory limit"
expect_in err.txt "(command line):1: memory limit of 1024 MB exceeded (a request of 1907.3 MB was refused)" "--safe: default memory limit message"

# --- 4. drawing far off the picture costs what is visible ---
measure "$POINTCALC" -e 'bezier{P(0, 0), P(1e15, 1e14), P(0, 1e15)}:draw()' -o far.png
expect_rc 0 "a Bezier curve out to 1e15"
expect_peak_below 50 "a Bezier curve out to 1e15"
measure "$POINTCALC" -e 'local p = {} for i = 1, 51 do p[i] = P((-1)^i * 10^(i % 19), (i % 7) * 10^(i % 18)) end bspline(p, 2):draw()' -o far.png
expect_rc 0 "a B-spline out to 1e18"
expect_peak_below 50 "a B-spline out to 1e18"
# a flattening too fine for any picture: a clear message, not gigabytes
measure "$POINTCALC" -e 'local p = {} for i = 1, 2e4 do p[i] = P(320 + 300 * math.cos(i), 240 + 200 * math.sin(1.1 * i)) end bspline(p, 3):draw{tol = 1e-9}'
expect_rc 1 "a flattening past the vertex cap"
expect_in err.txt "(command line):1: c:draw: the curve needs more than 4194304 vertices at tol = 1e-09 px; draw it with a larger tol" "the vertex cap's message"
expect_peak_below 200 "the vertex cap bounds the memory"

# --- 5. --frames with an SVG output follows the file-writing rules ---
cat > anim.lua <<'LUA'
local t = slider("t", 0, 1, 0, {animate = true})
circle(320, 240, 50 + 100 * t, 14)
label('url(#c1) id="c2"', P(100, 100))
LUA
printf 'keep' > ro.svg && chmod 444 ro.svg
run "$POINTCALC" anim.lua --frames 2 -o ro.svg; expect_rc 1 "--frames over a read-only file"
expect_in err.txt "cannot write 'ro.svg': Permission denied (the file is read-only)" "--frames: read-only"
expect_eq "$(cat ro.svg)" "keep" "--frames: the read-only file is kept"
mkfifo fifo.svg
run "$POINTCALC" anim.lua --frames 2 -o fifo.svg; expect_rc 1 "--frames over a FIFO"
expect_in err.txt "it is not a regular file" "--frames: FIFO"
checks=$((checks + 1)); [ -p fifo.svg ] || fail "--frames replaced the FIFO"
printf 'old' > mode.svg && chmod 640 mode.svg
run "$POINTCALC" anim.lua --frames 2 -o mode.svg; expect_rc 0 "--frames over a file"
expect_eq "$(stat -c %a mode.svg)" "640" "--frames keeps the mode"
expect_in mode.svg "<animate" "--frames: an animated SVG"
expect_in mode.svg "url(#c1) id=&quot;c2&quot;</text>" "--frames: label text not rewritten"
printf 'target' > elsewhere.txt && ln -s elsewhere.txt planted.svg.frames~
run "$POINTCALC" anim.lua --frames 2 -o planted.svg; expect_rc 0 "--frames beside a planted link"
expect_eq "$(cat elsewhere.txt)" "target" "--frames: a planted .frames~ link's target is untouched"
expect_eq "$(ls -A | grep -c '^\.')" "0" "--frames: no temporary file left"

# --- 2, 7, 8: the server survives every render; idle connections; the script's folder ---
mkdir site other
cat > site/fig.lua <<'LUA'
local case = slider("case", 0, 5, 0, {step = 1})
local tol = slider("tol", 1e-9, 1, .25)
if case == 1 then ("a"):rep(3e5):find(".-.-.-.-.-.-.-b") end
if case == 2 then setmetatable({}, {__gc = function() while true do end end}) collectgarbage() end
if case == 3 then xpcall(function() error("x") end, function() while true do end end) end
if case == 4 then
  local p = {} for i = 1, 2e4 do p[i] = P(320 + 300 * math.cos(i), 240 + 200 * math.sin(1.1 * i)) end
  bspline(p, 3):draw{tol = tol}
end
if case == 5 then error("plain") end
label(io.open("data.txt"):read("l"), P(20, 20))
LUA
printf 'beside the script\n' > site/data.txt
: >serve.txt
(cd other && exec "$POINTCALC" serve ../site/fig.lua --port 0) >serve.txt 2>serve_err.txt & server=$!
n=0; while ! grep -q "http://" serve.txt && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
url=$(grep -o 'http://[0-9.:]*/' serve.txt)
get() {  # get PATH OUT: the body in OUT, the status in $code
    code=$(python3 - "$url$1" "$2" <<'PY'
import sys, urllib.request, urllib.error
try:
    r = urllib.request.urlopen(sys.argv[1], timeout=20); body = r.read(); code = r.status
except urllib.error.HTTPError as e:
    body = e.read(); code = e.code
except Exception as e:
    body = str(e).encode(); code = 0
open(sys.argv[2], "wb").write(body); print(code)
PY
)
}
get "render" ok.svg
expect_eq "$code" 200 "serve: a render"
expect_in ok.svg "beside the script" "serve: a relative name resolves in the script's folder"
for c in 1 2 3; do
    get "render?case=$c" stop.txt
    expect_eq "$code" 422 "serve: runaway case $c answered 422"
    expect_in stop.txt "fig.lua:" "serve: case $c names the script"
    expect_in stop.txt "time limit of 2 s exceeded" "serve: case $c says why"
    get "render" after.svg
    expect_eq "$code" 200 "serve: the server goes on after case $c"
done
get "render?case=4&tol=1e-9" stop.txt
expect_eq "$code" 422 "serve: a slider driving a huge draw answered 422"
expect_in stop.txt "fig.lua:8: " "serve: the huge draw names its line (the vertex cap or the time limit, whichever comes first)"
get "render?case=5" stop.txt
expect_in stop.txt "fig.lua:10: plain" "serve: a plain error"
expect_not_in_file() { checks=$((checks + 1)); ! grep -qF -- "$2" "$1" || fail "$3"; }
expect_not_in_file stop.txt "$WORK" "serve: a 422 text carries no absolute path"
get "params" params.json
expect_in params.json '"script": "fig.lua"' "serve: /params"
# 1,100 idle connections do not lock out a new client
python3 - "$url" >idle.txt 2>&1 <<'PY'
import resource, socket, sys, urllib.request
soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
resource.setrlimit(resource.RLIMIT_NOFILE, (min(hard, 4096), hard))
host, port = sys.argv[1].split("//")[1].rstrip("/").split(":")
idle = [socket.create_connection((host, int(port))) for _ in range(1100)]
r = urllib.request.urlopen(sys.argv[1] + "render", timeout=10)
print("status", r.status)
PY
expect_in idle.txt "status 200" "serve: a new client after 1,100 idle connections"
kill $server; wait $server 2>/dev/null

finish
