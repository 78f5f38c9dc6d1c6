# --emit-lua: the translation keeps every source line on its own Lua line with the source as a
# comment, and the printed Lua runs in pointcalc with the same results as the program.
. "$(dirname "$0")/lib.sh"

for name in for_float32 procs graphics data records statics using; do
    cp "$QB_DIR/progs/$name.bas" "$name.bas"
    run "$POINTCALC" --emit-lua "$name.bas"
    expect_rc 0 "--emit-lua $name"
    mv out.txt "$name.lua"
    expect_eq "$(wc -l < "$name.lua")" "$(wc -l < "$name.bas")" "$name: one Lua line per source line"
    # every non-blank source line is carried as a comment on its own line number
    i=0
    bad=0
    while IFS= read -r src; do
        i=$((i + 1))
        [ -z "$(printf '%s' "$src" | tr -d ' \t')" ] && continue
        line=$(sed -n "${i}p" "$name.lua")
        case "$line" in *"-- $src") ;; *) bad=$((bad + 1)) ;; esac
    done < "$name.bas"
    expect_eq "$bad" 0 "$name: source lines carried as comments"
    run "$POINTCALC" "$name.lua" -o "$name.ppm"
    expect_rc 0 "running the emitted $name.lua"
    check
    diff -q out.txt "$QB_DIR/progs/$name.out" >/dev/null || fail "$name.lua prints differently"
done
# readable Lua using the drawing layer
expect_in graphics.lua 'circle(200, 200, 50, 14)' "graphics: CIRCLE becomes circle()"
expect_in graphics.lua 'line(50, 50, 60, 60, 3, "b")' "graphics: LINE ... B"
expect_in for_float32.lua 'do local _step = csng(.001) t = 0.0 while t <= 1 do' "FOR with a float32 step"
expect_in procs.lua 'x, y = swapit(x, y)' "SUB arguments copied back"

# the host picks QBasic by extension, or by --qbasic
printf 'PRINT 6 * 7\n' > answer.txt
run "$POINTCALC" --qbasic answer.txt
expect_rc 0 "--qbasic"
expect_eq "$(cat out.txt)" " 42 " "--qbasic runs QBasic"
# a runtime error names the program's line even in the emitted Lua, which keeps the lines
printf 'x = 1\nDATA 1\nREAD a, b\n' > ood.bas
run "$POINTCALC" --emit-lua ood.bas
mv out.txt ood.lua
run "$POINTCALC" ood.lua
expect_rc 1 "emitted Lua: runtime error"
expect_eq "$(head -n 1 err.txt)" "ood.lua:3: Out of DATA" "emitted Lua: error on the same line"
finish
