# The fuzzers over the paths issue 26 added: the server's render path (each render a child
# process) and --frames' animated SVG, driven by tests/fuzz/api_fuzz.lua with a seed from the
# query.  Every answer must be 200 or 422 with a message (never a crash of a render, never a
# dead server); --frames must end with status 0 or 1, never of a signal.
. "$(dirname "$0")/lib.sh"
FUZZ="$PC_SOURCE_DIR/tests/fuzz"

mkdir site && cp "$FUZZ/api_fuzz.lua" site/
cat > site/fig.lua <<'LUA'
local seed = slider("seed", 1, 1e6, 1, {step = 1})
arg = {[0] = "api_fuzz.lua", tostring(seed), "300", "fuzz.log"}
dofile("api_fuzz.lua")
LUA
: >serve.txt
"$POINTCALC" serve site/fig.lua --port 0 >serve.txt 2>serve_err.txt & server=$!
n=0; while ! grep -q "http://" serve.txt && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
url=$(grep -o 'http://[0-9.:]*/' serve.txt)
python3 - "$url" >answers.txt 2>&1 <<'PY'
import sys, urllib.request, urllib.error
url = sys.argv[1]
for seed in range(1, 41):
    try:
        r = urllib.request.urlopen(f"{url}render?seed={seed}", timeout=20); code, body = r.status, r.read()
    except urllib.error.HTTPError as e:
        code, body = e.code, e.read()
    except Exception as e:
        code, body = 0, str(e).encode()
    text = body.decode("utf-8", "replace")
    ok = code == 200 and text.startswith("<?xml") or code == 422 and "fig.lua:" in text or \
         code == 422 and "api_fuzz.lua:" in text
    crash = "ended of signal" in text or "without an answer" in text
    print(seed, code, "ok" if ok and not crash else "BAD " + text[:300].replace("\n", " "))
r = urllib.request.urlopen(f"{url}params", timeout=20)
print("params", r.status)
PY
kill $server; wait $server 2>/dev/null
expect_eq "$(grep -c ' ok$' answers.txt)" "40" "serve fuzz: 40 renders answered ($(grep BAD answers.txt | head -3))"
expect_in answers.txt "params 200" "serve fuzz: the server is alive after them"

# --frames over fuzzed runs: every frame a different seed
cat > site/anim.lua <<'LUA'
local t = slider("t", 1, 8, 1, {animate = true})
arg = {[0] = "api_fuzz.lua", tostring(math.floor(t) + 100), "300", "fuzz.log"}
dofile("api_fuzz.lua")
LUA
(cd site && "$POINTCALC" --safe --allow . anim.lua --frames 8 -o anim.svg) >out.txt 2>err.txt; rc=$?
checks=$((checks + 1)); [ "$rc" -le 1 ] || fail "--frames fuzz: status $rc ($(tail -c 300 err.txt))"
expect_eq "$(ls -A site | grep -c '^\.')" "0" "--frames fuzz: no temporary file"
checks=$((checks + 1))
! grep -q "AddressSanitizer\|runtime error:" err.txt serve_err.txt || fail "sanitizer report: $(grep -m2 'ERROR\|runtime error' err.txt serve_err.txt)"

finish
