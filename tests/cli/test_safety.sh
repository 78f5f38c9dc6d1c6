# Hardening (issue 15, docs/safety.md): each defect the reliability probe found, the rules for
# writing files, the safe mode and the time and memory limits.
. "$(dirname "$0")/lib.sh"

# crashed: did the process die of a signal or a sanitizer report?
expect_no_crash() {
    checks=$((checks + 1))
    if [ "$rc" -gt 2 ] || grep -q "AddressSanitizer\|runtime error:\|Segmentation" err.txt; then
        fail "$1: crashed (status $rc): $(grep -m2 "ERROR\|runtime error\|SUMMARY" err.txt)"
    fi
}
expect_not_in() {  # expect_not_in FILE TEXT DESCRIPTION
    checks=$((checks + 1))
    ! grep -qF -- "$2" "$1" || fail "$3: '$2' should not be in $1: $(head -c 400 "$1")"
}
temporaries() { ls -A "${1:-.}" | grep -c '^\.' ; }

# --- 1. the REPL reads piped bytes without the line editor: a NUL byte is reported, never a
# heap corruption in libedit ---
printf 'x=1\000bbbb\nprint(x)\nprint(2 + 3)\n' | "$POINTCALC" -i >out.txt 2>err.txt; rc=$?
expect_rc 0 "NUL byte in piped REPL input"
expect_in err.txt "stdin:1: the line contains a NUL byte; it is skipped" "NUL byte message"
expect_in out.txt "nil" "the line with the NUL byte did not run"
expect_in out.txt "5" "the REPL goes on after it"
# 200 kB of seeded random bytes (mostly not Lua): error messages, no crash
python3 -c 'import random, sys; r = random.Random(15); sys.stdout.buffer.write(bytes(r.randrange(256) for _ in range(200000)))' > noise.bin
"$POINTCALC" -i <noise.bin >out.txt 2>err.txt; rc=$?
expect_rc 0 "random bytes into the REPL"
expect_no_crash "random bytes into the REPL"
# the same bytes as a script: an error with a line, no crash
run "$POINTCALC" noise.bin; expect_rc 1 "random bytes as a script"
expect_in err.txt "noise.bin:" "random bytes as a script: located"

# --- 2. writing never replaces what is not a regular picture file ---
mkfifo pipe.png
ln -s pipe.png link.png
run "$POINTCALC" -e 'pset(1, 1)' -o link.png; expect_rc 1 "-o through a link to a pipe"
expect_in err.txt "cannot write 'link.png': it is not a regular file (a device, pipe or socket); pointcalc replaces only regular files" "link to a pipe"
checks=$((checks + 1)); [ -p pipe.png ] || fail "the pipe was replaced"
checks=$((checks + 1)); [ -L link.png ] || fail "the link was replaced"
printf 'pset(1, 1)\nsave("pipe.png")\n' > topipe.lua
run "$POINTCALC" topipe.lua; expect_rc 1 "save() over a pipe"
expect_in err.txt "topipe.lua:2: save: cannot write 'pipe.png': it is not a regular file" "save() over a pipe"
# a dangling link: nothing is created where it points
ln -s elsewhere/new.png dangling.png
run "$POINTCALC" -e 'pset(1, 1)' -o dangling.png; expect_rc 1 "dangling link"
expect_in err.txt "cannot write 'dangling.png': it is a symbolic link to a missing file" "dangling link"
# a link to a regular file: written through, the link stays
mkdir real && printf 'old' > real/pic.ppm && ln -s real/pic.ppm pic.ppm
run "$POINTCALC" -e 'pset(1, 1)' -o pic.ppm; expect_rc 0 "link to a regular file"
expect_eq "$(head -c 2 real/pic.ppm)" "P6" "written through the link"
checks=$((checks + 1)); [ -L pic.ppm ] || fail "the link to a regular file was replaced"
# a read-only file is kept, also when pointcalc runs as root
printf 'keep' > ro.png && chmod 444 ro.png
run "$POINTCALC" -e 'pset(1, 1)' -o ro.png; expect_rc 1 "read-only file"
expect_in err.txt "cannot write 'ro.png': Permission denied (the file is read-only)" "read-only file"
expect_eq "$(cat ro.png)" "keep" "read-only file untouched"
# a NUL byte in a path is an error, not a shorter name
run "$POINTCALC" -e 'pset(1, 1) save("a\0b.png")'; expect_rc 1 "NUL in save()"
expect_in err.txt "(command line):1: save: argument #1 (file name) must be a name without NUL bytes, got 'a\\0b.png'" "NUL in save()"
expect_no_file a "no truncated file"
run "$POINTCALC" -e 'io.open("c\0d.txt", "w")'; expect_rc 1 "NUL in io.open"
expect_in err.txt "io.open: argument #1 (file name) must be a name without NUL bytes" "NUL in io.open"
expect_no_file c "no truncated file"
expect_eq "$(temporaries)" "0" "no temporary files after refused writes"

# --- 3. a save stopped by a signal or a file-size limit leaves no temporary file ---
printf 'for i = 0, 479 do line(0, i, 639, 479 - i, i %% 16) end\nwhile true do save(arg[1] .. "/x.png") end\n' > saveloop.lua
for sig in TERM HUP TERM HUP; do   # (a background job of sh ignores SIGINT; test_write_file.c covers it)
    rm -rf sig; mkdir sig
    "$POINTCALC" saveloop.lua sig 2>/dev/null & pid=$!
    n=0
    while [ "$(temporaries sig)" = 0 ] && [ $n -lt 2000 ]; do sleep 0.01; n=$((n + 1)); done
    kill -$sig $pid; wait $pid; rc=$?
    expect_eq "$(temporaries sig)" "0" "SIG$sig during a save: no temporary file"
    checks=$((checks + 1)); [ "$rc" -gt 128 ] || fail "SIG$sig: status $rc, want death by the signal"
done
rm -rf sig; mkdir sig
printf 'pset(1, 1)\n' > dot.lua
# (SIGXFSZ back to its default action, which kills: a shell cannot undo an inherited "ignore")
(ulimit -f 1; python3 -c 'import os, signal, sys; signal.signal(signal.SIGXFSZ, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
    "$POINTCALC" dot.lua -o sig/big.ppm >out.txt 2>err.txt); rc=$?
expect_rc 1 "file-size limit"
expect_in err.txt "cannot write 'sig/big.ppm': File too large" "file-size limit message"
expect_eq "$(temporaries sig)" "0" "file-size limit: no temporary file"
expect_no_file sig/big.ppm "file-size limit: no partial file"

# --- 4. binary chunks: load refuses them (a mutated one crashed the interpreter) ---
run "$POINTCALC" -e 'local s = string.dump(function(a) return a + 1 end)
  s = s:sub(1, 20) .. string.char(255, 255, 255, 127) .. s:sub(25)
  print(load(s))
  print(load(string.dump(function() end), "x", "bt"))'
expect_rc 0 "load of a binary chunk"
expect_eq "$(cat out.txt)" "$(printf "nil\tattempt to load a binary chunk (mode is 't')\nnil\tattempt to load a binary chunk (mode is 't')")" "load refuses binary chunks"
# load with and without an environment: one not given is not an explicit nil
run "$POINTCALC" -e 'x = 5 print(load("return x")(), load("return x", "c", "t", {x = 7})(), (pcall(load("return x", "c", "t", nil))))'
expect_eq "$(cat out.txt)" "$(printf '5\t7\tfalse')" "load keeps _ENV unless one is given"
printf 'return 6 * 7' > six.lua
run "$POINTCALC" -e 'print(dofile("six.lua"), loadfile("six.lua")())'
expect_eq "$(cat out.txt)" "$(printf '42\t42')" "dofile and loadfile read source"
"$POINTCALC" -e 'local f = io.open("bin.luac", "wb") f:write(string.dump(function() return 1 end)) f:close()'
run "$POINTCALC" -e 'print(loadfile("bin.luac"))'
expect_in out.txt "attempt to load a binary chunk" "loadfile refuses binary chunks"

# --- 8. REPL messages name the command, not a line inside the REPL ---
printf ':show 0\n:show 2001\n' | "$POINTCALC" -i >out.txt 2>err.txt
expect_in err.txt ":show: COLUMNS must be a whole number from 4 to 2000, got 0" ":show 0"
expect_in err.txt ":show: COLUMNS must be a whole number from 4 to 2000, got 2001" ":show 2001"
expect_not_in err.txt "[pointcalc/" ":show: no internal location"

# --- the safe mode: each forbidden capability is a clear error ---
safe_refuses() {  # safe_refuses CODE MESSAGE
    run "$POINTCALC" --safe -e "$1"
    expect_rc 1 "--safe: $1"
    expect_in err.txt "$2" "--safe: $1"
}
safe_refuses 'os.execute("touch executed")' "(command line):1: os.execute is not available in safe mode (pointcalc --safe)"
safe_refuses 'io.popen("touch popened")' "io.popen is not available in safe mode"
safe_refuses 'package.loadlib("libc.so.6", "puts")' "package.loadlib is not available in safe mode"
safe_refuses 'os.exit(0)' "os.exit is not available in safe mode"
safe_refuses 'os.getenv("HOME")' "os.getenv is not available in safe mode"
safe_refuses 'debug.setmetatable(io.stdout, getmetatable(P(1, 2)))' "attempt to index a nil value (global 'debug')"
safe_refuses 'require "debug"' "module 'debug' not found"
safe_refuses 'package.cpath = "/usr/lib/x86_64-linux-gnu/lua/5.4/?.so" require "lpeg"' "module 'lpeg' not found"
printf 'return 1\n' > mod.lua
safe_refuses 'package.path = "./?.lua" require "mod"' "module 'mod' not found"
safe_refuses 'assert(load(string.dump(function() end)))' "attempt to load a binary chunk"
safe_refuses 'io.open("x.txt", "w")' "(command line):1: io.open: argument #1 (file name) must be a file under a folder given with --allow (in safe mode no folder is written without one), got 'x.txt'"
safe_refuses 'io.lines("six.lua")' "io.lines: argument #1 (file name) must be a file under a folder given with --allow"
safe_refuses 'dofile("six.lua")' "dofile: argument #1 (file name) must be a file under a folder given with --allow"
safe_refuses 'os.remove("six.lua")' "os.remove: argument #1 (file name) must be a file under a folder given with --allow"
expect_no_file executed "os.execute did not run"
expect_no_file popened "io.popen did not run"
expect_file six.lua "os.remove did not remove"

# files under --allow: reading and writing work; outside, or through a link out of it, not
mkdir box outside
ln -s ../outside box/escape
run "$POINTCALC" --safe --allow box -e 'local f = assert(io.open("box/note.txt", "w")) f:write("hi") f:close()
  print(io.open("box/note.txt"):read("a"))
  pset(1, 1) save("box/pic.svg") print("saved")'
expect_rc 0 "--safe --allow: allowed writes"
expect_eq "$(cat out.txt)" "$(printf 'hi\nsaved')" "--safe --allow: read back"
expect_file box/pic.svg "--safe --allow: save()"
run "$POINTCALC" --safe --allow box -e 'pset(1, 1) save("box/escape/pic.png")'
expect_rc 1 "--safe: a link out of the allowed folder"
expect_in err.txt "save: argument #1 (file name) must be a file under an allowed folder (" "--safe: a link out of the allowed folder"
expect_no_file outside/pic.png "--safe: nothing written through the link"
run "$POINTCALC" --safe --allow box -e 'io.open("box/../six.lua")'
expect_rc 1 "--safe: .. out of the allowed folder"
# -o is the user's own choice: the host writes it in safe mode too
run "$POINTCALC" --safe -e 'pset(2, 2)' -o safe_out.png; expect_rc 0 "--safe with -o"
expect_file safe_out.png "--safe with -o"
# the REPL works in safe mode (it keeps the debug library for itself)
printf 'mid(P(0, 0), P(2, 4))\nlerp\n:save /tmp/pc_safe_escape.png\nprint(debug)\n' | "$POINTCALC" --safe -i >out.txt 2>err.txt
expect_in out.txt "P(1, 2)" "--safe REPL: values"
expect_in out.txt "function lerp(A, B, t)" "--safe REPL: describing a function"
expect_in err.txt "cannot write '/tmp/pc_safe_escape.png': it must be a file under a folder given with --allow" "--safe REPL: :save"
expect_in out.txt "nil" "--safe REPL: no debug for the user"
expect_no_file /tmp/pc_safe_escape.png "--safe REPL: :save refused"

# usage errors
run "$POINTCALC" --allow box -e 'x = 1'; expect_rc 2 "--allow without --safe"
expect_in err.txt "--allow belongs to the safe mode: add --safe" "--allow without --safe"
run "$POINTCALC" --safe --allow no_such_dir -e 'x = 1'; expect_rc 2 "--allow of a missing folder"
expect_in err.txt "--allow 'no_such_dir': No such file or directory" "--allow of a missing folder"
run "$POINTCALC" --timeout soon -e 'x = 1'; expect_rc 2 "--timeout soon"
expect_in err.txt "option --timeout must be a positive number, got 'soon'" "--timeout soon"
run "$POINTCALC" --max-memory -5 -e 'x = 1'; expect_rc 2 "--max-memory -5"

# --- limits: a clear error at the script's line, no output written ---
printf 'pset(1, 1)\nlocal n = 0\nwhile true do n = n + 1 end\n' > loop.lua
run "$POINTCALC" --timeout 0.5 loop.lua -o loop.png; expect_rc 1 "--timeout"
expect_in err.txt "loop.lua:3: time limit of 0.5 s exceeded" "--timeout message"
expect_no_file loop.png "--timeout: no output"
# catching the error does not buy more time
printf 'while true do pcall(function() while true do end end) end\n' > catch.lua
run "$POINTCALC" --timeout 0.3 catch.lua; expect_rc 1 "--timeout through pcall"
expect_in err.txt "catch.lua:1: time limit of 0.3 s exceeded" "--timeout through pcall"
# a native call that runs on: stopped a grace period after the limit
run "$POINTCALC" --timeout 0.2 -e 'string.rep("a", 60):find(string.rep("a?", 60) .. string.rep("a", 60))'
expect_rc 1 "--timeout in a native call"
expect_in err.txt "(command line):1: time limit of 0.2 s exceeded in a native call; stopped" "--timeout in a native call"
printf 'pset(1, 1)\nlocal t = {}\nfor i = 1, 1e8 do t[i] = {i} end\n' > grow.lua
run "$POINTCALC" --max-memory 40 grow.lua; expect_rc 1 "--max-memory"
expect_in err.txt "grow.lua:3: memory limit of 40 MB exceeded" "--max-memory message"
expect_no_file grow.png "--max-memory: no output"
run "$POINTCALC" --max-memory 40 -e 'local s = string.rep("x", 1e9)'; expect_rc 1 "--max-memory, one big allocation"
expect_in err.txt "(command line):1: memory limit of 40 MB exceeded (a request of 953.7 MB was refused)" "one big allocation"
# within the limits a script runs as before
run "$POINTCALC" --timeout 5 --max-memory 100 -e 'local t = {} for i = 1, 1e5 do t[i] = P(i, i) end print(#t)'
expect_eq "$(cat out.txt)" "100000" "within the limits"
# the REPL: each statement has the time limit, and the session goes on
printf 'while true do end\nprint("after")\n' | "$POINTCALC" --timeout 0.3 -i >out.txt 2>err.txt
expect_in err.txt "stdin:1: time limit of 0.3 s exceeded" "--timeout in the REPL"
expect_in out.txt "after" "the REPL goes on after a time limit"

finish
