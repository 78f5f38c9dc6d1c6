#!/bin/sh
# Installing pointcalc: `cmake --install` into a temporary prefix, then the program, an example,
# the Lua module, the man page and the bash completion used from there with nothing from the build
# or source folder on any path; the rockspec (luarocks lint, luarocks make --tree); the .deb
# (cpack: its metadata and contents read with dpkg-deb, then unpacked and run in a folder; it is
# never installed system-wide here).
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
build=$(dirname "$POINTCALC")
prefix=$WORK/prefix
version=$("$POINTCALC" -v | sed -n 's/^pointcalc \([^ ]*\).*/\1/p')
oval=share/pointcalc/examples/stepanov/02_oval_in_quadrilateral.lua

# a sanitizer build of the module needs the sanitizer runtime loaded before lua5.4 starts
preload=
if [ "$PC_SANITIZE" = 1 ]; then
    preload="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)"
fi
# clean CMD...: runs CMD in an empty environment with only ROOT's bin and the system on PATH
clean() {
    env -i PATH="$ROOT/bin:/usr/bin:/bin" HOME="$WORK" LD_PRELOAD="$preload" \
        ASAN_OPTIONS=detect_leaks=0 "$@" >out.txt 2>err.txt
    rc=$?
}
# the reference pictures, drawn by the build's program
"$POINTCALC" "$PC_SOURCE_DIR/examples/stepanov/02_oval_in_quadrilateral.lua" -o ref_oval.png >/dev/null
"$POINTCALC" -e 'screen(12) circle(P(320, 240), 100, 14) line(P(0, 0), P(639, 479), 9)' -o ref_module.png

# use_tree ROOT LUADIR WHAT: the program, an example and the module from an installed tree
use_tree() {
    ROOT=$1
    mkdir -p "$WORK/run" && cd "$WORK/run"
    clean sh -c 'command -v pointcalc'
    expect_eq "$(cat out.txt)" "$ROOT/bin/pointcalc" "$3: pointcalc on PATH"
    clean pointcalc -v
    expect_eq "$(cat out.txt)" "$("$POINTCALC" -v)" "$3: pointcalc -v"
    clean pointcalc "$ROOT/$oval" -o oval.png
    expect_rc 0 "$3: example 2 runs"
    checks=$((checks + 1))
    cmp -s oval.png ../ref_oval.png || fail "$3: example 2 differs from the build's picture"
    # a variant loads its sibling script from the installed examples folder
    clean pointcalc "$ROOT/share/pointcalc/examples/stepanov/20v_colour8_grid.lua" -o v.png
    expect_rc 0 "$3: example 20v finds example 20 beside it"
    # the module in the stock interpreter, found through LUA_CPATH alone (no default path)
    clean env LUA_CPATH="$ROOT/$2/?.so" lua5.4 -e '
        local pc = require "pointcalc"
        print(package.searchpath("pointcalc", package.cpath), pc._VERSION)
        pc.screen(12) pc.circle(pc.P(320, 240), 100, 14) pc.line(pc.P(0, 0), pc.P(639, 479), 9)
        pc.save("module.png")'
    expect_rc 0 "$3: require \"pointcalc\" in lua5.4"
    expect_eq "$(cat out.txt)" "$(printf '%s\tpointcalc %s' "$ROOT/$2/pointcalc.so" "$version")" \
        "$3: the module comes from the installed tree"
    checks=$((checks + 1))
    cmp -s module.png ../ref_module.png || fail "$3: the module draws differently from the program"
    cd "$WORK"
}

# --- cmake --install into a temporary prefix ----------------------------------------------
run cmake --install "$build" --prefix "$prefix"
expect_rc 0 "cmake --install"
for f in bin/pointcalc lib/lua/5.4/pointcalc.so share/man/man1/pointcalc.1.gz \
         share/bash-completion/completions/pointcalc share/doc/pointcalc/README.md \
         share/doc/pointcalc/docs/api.md share/doc/pointcalc/docs/curves.png "$oval" \
         share/pointcalc/examples/render_gallery.sh; do
    expect_file "$prefix/$f" "installed"
done
checks=$((checks + 1))
readelf -d "$prefix/bin/pointcalc" "$prefix/lib/lua/5.4/pointcalc.so" | grep -q 'R.*PATH' &&
    fail "the installed binaries carry an RPATH: $(readelf -d "$prefix/bin/pointcalc" | grep PATH)"
use_tree "$prefix" lib/lua/5.4 "prefix"
# the installed examples render into a gallery with the installed program, as the README says
ROOT=$prefix
clean sh "$prefix/share/pointcalc/examples/render_gallery.sh" pointcalc "$WORK/gallery"
expect_rc 0 "the installed render_gallery.sh: $(head -3 err.txt)"
expect_eq "$(ls gallery/*/*.svg | grep -vc -- -animated.svg)" "$(ls "$PC_SOURCE_DIR"/examples/*/*.lua | wc -l)" \
    "the installed gallery has every example"

# --- the man page: written from --help, rendered by man without warnings -------------------
gzip -dc "$prefix/share/man/man1/pointcalc.1.gz" > pointcalc.1
groff -ww -man -Tutf8 -z pointcalc.1 2>groff.txt
expect_eq "$(cat groff.txt)" "" "groff -ww: no warnings"
run env MANWIDTH=100 man --warnings=w -l "$prefix/share/man/man1/pointcalc.1.gz"
expect_rc 0 "man -l"
expect_eq "$(cat err.txt)" "" "man -l: no warnings"
expect_in out.txt "pointcalc $version" "the man page's version is the program's"
"$POINTCALC" --help > help.txt
sed -n 's/^  \(-[^ ,]*\(, -[^ ,]*\)*\).*/\1/p' help.txt | tr ', ' '\n\n' | grep . > options.txt
sed -n '/^OPTIONS/,/^[A-Z]/p' out.txt > man_options.txt
while read -r opt; do
    checks=$((checks + 1))
    grep -qE -- "^ +$opt( |,|$)|, $opt( |$)" man_options.txt || fail "--help's option $opt is not in the man page"
done < options.txt
expect_eq "$(grep -cE '^ {7}-' man_options.txt)" "$(grep -c '^  -' help.txt)" "the man page has --help's options, no more"
run env MANPATH="$prefix/share/man" man -w pointcalc
expect_eq "$(cat out.txt)" "$prefix/share/man/man1/pointcalc.1.gz" "man finds the page under the prefix"

# --- bash completion: option names from --help, file names by what each option takes ------
mkdir comp && touch comp/a.lua comp/b.bas comp/c.png comp/d.txt
complete_words() {  # complete_words WORD...: the completions of the last word
    (cd comp && PATH="$prefix/bin:/usr/bin:/bin" bash -c 'shopt -s extglob
        . "$1"; shift
        COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _pointcalc
        printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "' \
        sh "$prefix/share/bash-completion/completions/pointcalc" "$@")
}
expect_eq "$(complete_words pointcalc --wa)" "--watch " "completion of --wa"
expect_eq "$(complete_words pointcalc --)" "$(grep '^--' options.txt | sort | tr '\n' ' ')" \
    "completion of --: every long option of --help"
expect_in options.txt "--emit-lua" "--help lists --emit-lua"
expect_eq "$(complete_words pointcalc -o '')" "c.png " "completion after -o: pictures"
expect_eq "$(complete_words pointcalc '')" "a.lua b.bas " "completion of the script: .lua and .bas"
expect_eq "$(complete_words pointcalc a.lua -)" "--paper --watch -o " "completion after the script"

# --- LuaRocks: the rockspec lints and `luarocks make` installs a working module ------------
rockspec=$PC_SOURCE_DIR/pointcalc-dev-1.rockspec
if ! command -v luarocks >/dev/null; then
    fail "luarocks is not installed (setup.sh installs it)"
else
    run luarocks lint "$rockspec"
    expect_rc 0 "luarocks lint: $(cat out.txt err.txt)"
    if [ "$PC_SANITIZE" = 1 ]; then
        echo "note: luarocks make is checked in the plain build, not under the sanitizers"
    else
        # a copy of the sources: luarocks builds in the folder it is run from
        mkdir src
        (cd "$PC_SOURCE_DIR" && tar --exclude='./build*' --exclude=./.git --exclude=./gallery -cf - .) |
            (cd src && tar -xf -)
        (cd src && MAKEFLAGS=-j$(nproc) luarocks --lua-version 5.4 --tree "$WORK/tree" make \
            pointcalc-dev-1.rockspec >"$WORK/luarocks.log" 2>&1)
        rc=$?
        expect_rc 0 "luarocks make --tree: $(tail -5 luarocks.log)"
        expect_file tree/lib/lua/5.4/pointcalc.so "luarocks installed the module"
        run env LUA_CPATH="$WORK/tree/lib/lua/5.4/?.so" lua5.4 -e '
            local pc = require "pointcalc"; print(pc._VERSION, pc.dist(pc.P(0, 0), pc.P(3, 4)))'
        expect_eq "$(cat out.txt)" "$(printf 'pointcalc %s\t5.0' "$version")" "the rock's module works"
        run luarocks --lua-version 5.4 --tree "$WORK/tree" list --porcelain
        expect_in out.txt "pointcalc	dev-1	installed" "luarocks lists the rock"
    fi
fi

# --- the .deb: cpack, its control fields and files, unpacked and used ------------------------
if [ "$PC_SANITIZE" = 1 ]; then
    echo "note: the .deb is built from the plain build, not from the sanitizer build"
else
    run cpack -G DEB --config "$build/CPackConfig.cmake" -B "$WORK/deb"
    expect_rc 0 "cpack -G DEB: $(tail -3 out.txt)"
    arch=$(dpkg --print-architecture)
    deb=$WORK/deb/pointcalc_${version}_$arch.deb
    expect_file "$deb" "the .deb"
    field() { dpkg-deb -f "$deb" "$1"; }
    expect_eq "$(field Package)" "pointcalc" "Package"
    expect_eq "$(field Version)" "$version" "Version is the program's"
    expect_eq "$(field Architecture)" "$arch" "Architecture"
    expect_eq "$(field Section)" "graphics" "Section"
    expect_eq "$(field Recommends)" "lua5.4" "Recommends"
    for dep in libc6 liblua5.4-0 libpng16-16 libcairo2 libpango-1.0-0 fonts-cmu; do
        checks=$((checks + 1))
        field Depends | grep -q "$dep\( (>=\|,\|$\)" || fail "Depends lacks $dep: $(field Depends)"
    done
    # every dependency is a package this system has, so dpkg -i can satisfy it
    for dep in $(field Depends | tr ',' '\n' | sed 's/(.*//; s/ //g'); do
        checks=$((checks + 1))
        dpkg-query -W -f='${Status}' "$dep" 2>/dev/null | grep -q "ok installed" ||
            fail "dependency $dep is not installed here"
    done
    dpkg-deb -c "$deb" | awk '{ print $NF }' > contents.txt
    for f in usr/bin/pointcalc usr/lib/lua/5.4/pointcalc.so usr/share/man/man1/pointcalc.1.gz \
             usr/share/bash-completion/completions/pointcalc usr/share/doc/pointcalc/README.md \
             "usr/$oval"; do
        expect_in contents.txt "./$f" "the package holds /$f"
    done
    expect_eq "$(grep -v '^\./usr/' contents.txt | grep -v '^\./$')" "" "nothing outside /usr"
    dpkg-deb -x "$deb" root
    use_tree "$WORK/root/usr" lib/lua/5.4 "unpacked .deb"
fi
finish
