# No product Lua function longer than 200 lines (issue 20): the QBasic passes and the runtime are
# modules of named functions over an explicit state, not one closure per pass.  `luac5.4 -p -l`
# lists every function of a file with its first and last line; each of interp/ and stdlib/lua
# is checked.
. "$(dirname "$0")/lib.sh"
MAX=200
LUAC=$(command -v luac5.4 || command -v luac)
check
[ -n "$LUAC" ] || fail "luac5.4 not found (the lua5.4 package): cannot list the functions"

n=0
for f in $(cd "$PC_SOURCE_DIR" && find interp stdlib/lua -name '*.lua' | sort); do
    n=$((n + 1))
    check
    if ! "$LUAC" -p -l "$PC_SOURCE_DIR/$f" >listing.txt 2>luac_err.txt; then
        fail "$f: luac cannot read it: $(head -c 300 luac_err.txt)"
        continue
    fi
    # "function <FILE:FIRST,LAST> (...)": the span of each function (main is the whole file)
    sed -n 's/^function <[^>]*:\([0-9]*\),\([0-9]*\)>.*/\1 \2/p' listing.txt >spans.txt
    check
    [ -s spans.txt ] || [ "$(grep -c '^function <' listing.txt)" = 0 ] || fail "$f: no spans read from the listing"
    while read -r first last; do
        [ $((last - first + 1)) -le $MAX ] ||
            fail "$f: the function at lines $first-$last spans $((last - first + 1)) lines (at most $MAX)"
    done <spans.txt
done
expect_eq "$([ "$n" -ge 20 ] && echo yes)" yes "at least 20 Lua files found under interp/ and stdlib/lua"

# the check itself sees a long function: a file with a 201-line function fails it
{ echo "local function f()"; for i in $(seq 1 199); do echo "  local x$i = $i"; done; echo "end"; } >long.lua
"$LUAC" -p -l long.lua | sed -n 's/^function <[^>]*:\([0-9]*\),\([0-9]*\)>.*/\1 \2/p' >spans.txt
read -r first last <spans.txt
expect_eq "$((last - first + 1))" 201 "the span of a 201-line function as luac lists it"
finish
