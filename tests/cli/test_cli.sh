# The pointcalc command line: exit codes, error format, outputs, arguments, the Lua module.
. "$(dirname "$0")/lib.sh"

# --- version, help, usage errors (exit 2) ---
run "$POINTCALC" -v;              expect_rc 0 "-v"; expect_in out.txt "pointcalc 0." "-v"
run "$POINTCALC" -h;              expect_rc 0 "-h"; expect_in out.txt "usage: pointcalc" "-h"
run "$POINTCALC" --frobnicate;    expect_rc 2 "unknown option"; expect_in err.txt "unknown option '--frobnicate'" "unknown option"
run "$POINTCALC" -e 'x=1' -o pic.gif; expect_rc 2 "unknown extension"
expect_in err.txt "cannot write 'pic.gif': the extension must be .png, .svg, .ppm, .pdf, .eps or .ps" "unknown extension"
run "$POINTCALC" -o;              expect_rc 2 "-o without a file"
run "$POINTCALC" no_such_script.lua; expect_rc 2 "missing script"
expect_in err.txt "cannot open 'no_such_script.lua'" "missing script"
mkdir folder.lua
run "$POINTCALC" folder.lua;      expect_rc 2 "a folder as the script"
expect_in err.txt "cannot open 'folder.lua': Is a directory" "a folder as the script"

# --- script errors: file:line: message and a traceback, exit 1 ---
printf 'local a = 1\n\nerror("boom")\n' > err.lua
run "$POINTCALC" err.lua;         expect_rc 1 "runtime error"
expect_in err.txt "err.lua:3: boom" "runtime error message"
expect_in err.txt "stack traceback:" "traceback"
printf 'x = = 1\n' > syntax.lua
run "$POINTCALC" syntax.lua;      expect_rc 1 "syntax error"; expect_in err.txt "syntax.lua:1:" "syntax error line"
printf 'screen(12)\n\ncircle(1, 2)\n' > badarg.lua
run "$POINTCALC" badarg.lua;      expect_rc 1 "bad argument"
expect_in err.txt "badarg.lua:3: circle: argument #3 (radius) must be a non-negative number, got nil" "argument error"
# errors found inside the toolkit's Lua helpers point at the script's line, not into pointcalc
printf 'local Q = bilinear(P(0, 0), P(1, 0), P(1, 1), P(0, 1))\n\nQ:draw(function(t) return "x" end, {t = {0, 1, .5}})\n' > lens.lua
run "$POINTCALC" lens.lua;        expect_rc 1 "toolkit error"
expect_in err.txt "lens.lua:3: a curve must return a point or numbers, got string" "toolkit error located in the script"
printf 'local Q = bilinear(P(0, 0), 2, 3, 4)\n' > bil.lua
run "$POINTCALC" bil.lua;         expect_in err.txt "bil.lua:1: bilinear: argument #2 (P1) must be a point, got 2" "binding error through a Lua helper"
run "$POINTCALC" -e 'pset(1)';    expect_rc 1 "-e error"; expect_in err.txt "(command line):1: pset: argument #2 (y) must be a number or a point, got nil" "-e error"
expect_no_file pointcalc.png "no output after an error"

# --- a precompiled chunk is refused, not run: Lua does not verify bytecode, and a damaged
# binary file would crash the interpreter ---
"$POINTCALC" -e 'local f = io.open("dumped.lua", "wb") f:write(string.dump(function() print("ran") end)) f:close()'
run "$POINTCALC" dumped.lua;      expect_rc 1 "precompiled chunk"
expect_in err.txt "cannot run 'dumped.lua': it is a precompiled Lua chunk; pointcalc runs source scripts" "precompiled chunk message"
expect_eq "$(cat out.txt)" "" "a precompiled chunk does not run"
run "$POINTCALC" -e "$(printf '\033Lua')"; expect_rc 1 "binary -e chunk"
expect_in err.txt "binary chunk" "binary -e chunk message"
printf 'pset(1, 1)\n\000\001\377\376\211PNG\n' > noise.lua
run "$POINTCALC" noise.lua;       expect_rc 1 "binary garbage as a script"
expect_in err.txt "noise.lua:2:" "binary garbage: the line of the first bad byte"

# --- several -o at once; exact pixels through PPM ---
printf 'pset(3, 0, 14)\nline(0, 1, 639, 1, 4)\n' > draw.lua
run "$POINTCALC" -o a.png -o a.svg draw.lua -o a.ppm
expect_rc 0 "several -o"
expect_file a.png "-o png"; expect_file a.svg "-o svg"; expect_file a.ppm "-o ppm"
expect_eq "$(head -c 15 a.ppm | tr '\n' ' ')" "P6 640 480 255 " "PPM header"
# pixel (3, 0) is yellow 14 = FF FF 55; pixel (0, 1) is red 4 = AA 00 00
expect_eq "$(od -An -tx1 -j $((15 + 9)) -N 3 a.ppm | tr -d ' ')" "ffff55" "PPM pixel (3,0)"
expect_eq "$(od -An -tx1 -j $((15 + 640 * 3)) -N 3 a.ppm | tr -d ' ')" "aa0000" "PPM pixel (0,1)"
expect_eq "$(head -c 8 a.png | od -An -tx1 | tr -d ' ')" "89504e470d0a1a0a" "PNG signature"
expect_in a.svg "<svg" "SVG root"
expect_no_file draw.png "no default output when -o is given"
run "$POINTCALC" --paper -o paper.ppm draw.lua
expect_eq "$(od -An -tx1 -j $((15 + (5 * 640 + 5) * 3)) -N 3 paper.ppm | tr -d ' ')" "ffffff" "paper background"

# --- the default output name ---
mkdir sub && printf 'circle(320, 240, 100)\n' > sub/ring.lua
run "$POINTCALC" sub/ring.lua;    expect_rc 0 "default output"
expect_file ring.png "default output in the current directory"
expect_in err.txt "wrote ring.png" "default output is announced"
printf 'pset(1, 1)\nsave("saved.svg")\n' > saves.lua
run "$POINTCALC" saves.lua;       expect_rc 0 "script that saves"
expect_file saved.svg "save()"; expect_no_file saves.png "no default output after save()"
printf 'x = 1\n' > quiet.lua
run "$POINTCALC" quiet.lua;       expect_no_file quiet.png "no output without drawing"

# --- unwritable paths: message, exit 1, no file left ---
printf 'pset(1, 1)\nsave("missing_dir/x.png")\n' > unwritable.lua
run "$POINTCALC" unwritable.lua;  expect_rc 1 "unwritable save"
expect_in err.txt "unwritable.lua:2: save: cannot write 'missing_dir/x.png': No such file or directory" "unwritable save message"
mkdir ro && chmod 555 ro
if [ "$(id -u)" != 0 ]; then
    run "$POINTCALC" -e 'pset(1,1)' -o ro/x.png; expect_rc 1 "unwritable -o"
    expect_in err.txt "cannot write 'ro/x.png'" "unwritable -o message"
fi
run "$POINTCALC" -e 'pset(1,1)' -o missing_dir/y.svg; expect_rc 1 "unwritable -o"
expect_in err.txt "cannot write 'missing_dir/y.svg'" "unwritable -o message"
expect_eq "$(ls ro missing_dir 2>/dev/null | tr -d '\n')" "ro:" "no temporary files left"

# --- arguments, -e, standard input ---
printf 'print(arg[0], arg[1], arg[2], select("#", ...), ...)\n' > args.lua
run "$POINTCALC" args.lua one -x -- two; expect_rc 0 "script arguments"
expect_eq "$(cat out.txt)" "$(printf 'args.lua\tone\t-x\t3\tone\t-x\ttwo')" "arg table and ..."
run "$POINTCALC" -e 'print(P and "P" or "no P", type(pset), pointcalc.pset == pset)'
expect_eq "$(cat out.txt)" "$(printf 'P\tfunction\ttrue')" "globals"
printf 'print(6 * 7)\n' | "$POINTCALC" - >out.txt 2>err.txt; rc=$?
expect_rc 0 "script from stdin"; expect_eq "$(cat out.txt)" "42" "script from stdin"
printf 'print(2 + 2)\n' | "$POINTCALC" >out.txt 2>err.txt
expect_eq "$(cat out.txt)" "4" "stdin without a terminal"
# -i asks for the REPL: it reads the piped lines (as lua5.4 -i does), not a script from them
printf 'mid(P(0, 0), P(4, 2))\n:help lerp\n' | "$POINTCALC" -i >out.txt 2>err.txt; rc=$?
expect_rc 0 "-i with piped input"
expect_in out.txt "P(2, 1)" "-i with piped input: an expression prints its value"
expect_in out.txt "lerp(A, B, t)" "-i with piped input: a command"

# --- the Lua module in the stock interpreter ---
# a sanitizer build of the module needs the sanitizer runtime loaded before lua5.4 starts
preload=
if [ "$PC_SANITIZE" = 1 ]; then
    preload="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)"
    export ASAN_OPTIONS=detect_leaks=0   # lua5.4 itself is not ours to check
fi
if command -v lua5.4 >/dev/null; then
    run env LD_PRELOAD="$preload" lua5.4 -e "package.cpath = '$PC_MODULE_DIR/?.so;' .. package.cpath
        local pc = require 'pointcalc'
        pc.screen(12); pc.pset(pc.P(5, 6), 12); pc.save('module.ppm')
        print(pc.point(5, 6), pc.dist(pc.P(0, 0), pc.P(3, 4)), pset == nil)"
    expect_rc 0 "require in lua5.4"
    expect_eq "$(cat out.txt)" "$(printf '12\t5.0\ttrue')" "module API"
    expect_file module.ppm "module save"
else
    fail "lua5.4 is not installed (setup.sh installs it)"
fi

finish
