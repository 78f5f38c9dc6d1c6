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
         share/man/man7/pointcalc-api.7.gz lib/libpointcalc.so.0 lib/pkgconfig/pointcalc.pc \
         include/pointcalc/pointcalc.h include/pointcalc/canvas.h include/pointcalc/point.h \
         share/pointcalc/lua-language-server/library/globals.lua \
         share/pointcalc/lua-language-server/library/pointcalc.lua \
         share/pointcalc/lua-language-server/library/types.lua \
         share/zsh/site-functions/_pointcalc share/doc/pointcalc/LICENSE share/doc/pointcalc/copyright \
         share/bash-completion/completions/pointcalc share/doc/pointcalc/README.md \
         share/doc/pointcalc/docs/api.md share/doc/pointcalc/docs/curves.png "$oval" \
         share/pointcalc/examples/render_gallery.sh; do
    expect_file "$prefix/$f" "installed"
done
# no absolute RPATH: only the RUNPATH that finds libpointcalc relative to the installed file
checks=$((checks + 1))
readelf -d "$prefix/bin/pointcalc" "$prefix/lib/lua/5.4/pointcalc.so" | grep 'R.*PATH' | grep -v '\[\$ORIGIN/' &&
    fail "the installed binaries carry an absolute RPATH"
expect_eq "$(readelf -d "$prefix/lib/libpointcalc.so.0" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')" \
    "libpointcalc.so.0" "the library's soname"
checks=$((checks + 1))
nm -D --defined-only "$prefix/lib/libpointcalc.so.0" | grep -v '@@POINTCALC_0$' | grep -v ' A POINTCALC_0$' |
    grep -q . && fail "libpointcalc exports symbols outside the version node POINTCALC_0"
checks=$((checks + 1))
nm -D --defined-only "$prefix/lib/libpointcalc.so.0" | grep -v ' pc' | grep -v POINTCALC_0 | grep -q . &&
    fail "libpointcalc exports names without the pc prefix"
checks=$((checks + 1))
readelf -d "$prefix/bin/pointcalc" | grep -q 'NEEDED.*libpointcalc.so.0' || fail "the program does not link libpointcalc"
checks=$((checks + 1))
readelf -d "$prefix/lib/lua/5.4/pointcalc.so" | grep -q 'NEEDED.*libpointcalc.so.0' ||
    fail "the Lua module does not link libpointcalc"

# --- the C library: the example compiled with pkg-config against the prefix, run ------------
mkdir cprog && cp "$PC_SOURCE_DIR/examples/c/figure.c" cprog/
expect_eq "$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --modversion pointcalc)" "$version" \
    "pkg-config --modversion is the program's version"
(cd cprog && PKG_CONFIG_PATH="$prefix/lib/pkgconfig" \
    sh -c 'cc -Wall -Wextra -Werror figure.c $(pkg-config --cflags --libs pointcalc) -o figure' >cc.txt 2>&1)
rc=$?
expect_rc 0 "cc figure.c \$(pkg-config --cflags --libs pointcalc): $(head -5 cprog/cc.txt)"
(cd cprog && LD_LIBRARY_PATH="$prefix/lib" LD_PRELOAD="$preload" ASAN_OPTIONS=detect_leaks=0 \
    ./figure fig.png >out.txt 2>err.txt)
rc=$?
expect_rc 0 "the example C program runs against the installed library"
expect_eq "$(cat cprog/out.txt)" "K = (260.7143, 189.2857), lambda = 0.8929
Bezier: 33 vertices" "the example's meet of the diagonals and its flattened Bezier"
# its figure: the oval's yellow (14) and the Bezier's cyan (11) pixels, and the meet's red circle
"$POINTCALC" -e '
  local img = assert(io.open("cprog/fig.png", "rb")):read("a")
  print(#img > 1000 and img:sub(2, 4) == "PNG")' > png.txt
expect_eq "$(cat png.txt)" "true" "the example writes a PNG"
checks=$((checks + 1))
LD_LIBRARY_PATH="$prefix/lib" ldd cprog/figure | grep -q "$prefix/lib/libpointcalc.so.0" || fail "the example does not use the installed library"
use_tree "$prefix" lib/lua/5.4 "prefix"
# the installed examples render into a gallery with the installed program, as the README says
ROOT=$prefix
clean env PC_GALLERY_PDF=0 sh "$prefix/share/pointcalc/examples/render_gallery.sh" pointcalc "$WORK/gallery"
expect_rc 0 "the installed render_gallery.sh: $(head -3 err.txt)"
expect_eq "$(ls gallery/*/*.svg | grep -vc -- -animated.svg)" "$(ls "$PC_SOURCE_DIR"/examples/*/*.lua | wc -l)" \
    "the installed gallery has every example"

# --- pointcalc-api(7): every name of the registry, rendered without warnings ----------------
# (a function by its name, an operator, field or method by the start of its first form)
"$POINTCALC" -e 'local H = require "help"
  for _, e in ipairs(H.entries) do
    print(e.kind, e.kind == "function" and e.name or H.forms(e)[1]:sub(1, 12))
  end' > names.txt
expect_eq "$(wc -l < names.txt | tr -d ' ')" "$("$POINTCALC" -e 'print(#require("help").entries)')" "the registry's names"
gzip -dc "$prefix/share/man/man7/pointcalc-api.7.gz" > api.7
groff -ww -man -Tutf8 -z api.7 2>groff7.txt
expect_eq "$(cat groff7.txt)" "" "groff -ww on pointcalc-api(7): no warnings"
run env MANWIDTH=200 man --warnings=w -l "$prefix/share/man/man7/pointcalc-api.7.gz"
expect_rc 0 "man -l pointcalc-api.7"
expect_eq "$(cat err.txt)" "" "man -l pointcalc-api.7: no warnings"
cp out.txt api.txt
while read -r kind name; do
    checks=$((checks + 1))
    grep -qF -- "$name" api.txt || fail "pointcalc-api(7) lacks $name"
done < names.txt
run env MANPATH="$prefix/share/man" man -w pointcalc-api
expect_eq "$(cat out.txt)" "$prefix/share/man/man7/pointcalc-api.7.gz" "man finds pointcalc-api(7)"

# --- the language-server definitions: Lua that parses, with every function of the registry ----
meta=$prefix/share/pointcalc/lua-language-server/library
for f in globals pointcalc types; do
    run luac5.4 -p "$meta/$f.lua"
    expect_rc 0 "luac -p $f.lua: $(cat err.txt)"
    expect_eq "$(head -1 "$meta/$f.lua" | cut -c1-8)" "---@meta" "$f.lua is a ---@meta file"
done
while read -r kind name; do
    [ "$kind" = function ] || continue
    checks=$((checks + 2))
    case $name in
        *.*) grep -qE "^function ($name|pointcalc\.$name)\(|^---@class pc\.global\.$name\$" "$meta/globals.lua" ||
                 fail "globals.lua lacks $name" ;;
        *)   grep -qE "^function $name\(|^$name = \{\}|^---@class pc\.global\.$name\$" "$meta/globals.lua" ||
                 fail "globals.lua lacks $name" ;;
    esac
    grep -qE "^function pointcalc\.$name\(|^pointcalc\.$name = |^---@class pc\.lib\.$name\$" "$meta/pointcalc.lua" ||
        fail "pointcalc.lua lacks $name"
done < names.txt
# every method of the registry (c:split, s:iso, f:inverse...) on its class
"$POINTCALC" -e 'local H = require "help"
  for _, e in ipairs(H.entries) do
    for _, f in ipairs(H.forms(e)) do
      for m in f:gmatch("%f[%w]%a:([%a_][%w_]*)%(") do print(m) end
    end
  end' | sort -u > methods.txt
checks=$((checks + 1)); [ "$(grep -c . methods.txt)" -gt 30 ] || fail "the registry lists few methods: $(cat methods.txt)"
while read -r m; do
    checks=$((checks + 1))
    grep -qE "^function [a-z]+:$m\(" "$meta/types.lua" || fail "types.lua lacks the method :$m"
done < methods.txt
# the value types, their methods and operators, and typed parameters with option keys
for want in '^---@class pc.point$' '^---@operator add(pc.point): pc.point$' '^function curve:split(t) end$' \
            '^---@field x number' '^function surface:iso(' '^---@operator mul(pc.map): pc.map$'; do
    checks=$((checks + 1))
    grep -q -- "$want" "$meta/types.lua" || fail "types.lua lacks $want"
done
expect_in "$meta/globals.lua" "---@param opts {A: pc.point, B: pc.point, C?: pc.point" "conic.circle's option keys"
expect_in "$meta/globals.lua" "---@param eps? number" "near's optional eps"
expect_in "$meta/globals.lua" "---@return pc.point" "a point result"

# --- the man page: written from --help, rendered by man without warnings -------------------
gzip -dc "$prefix/share/man/man1/pointcalc.1.gz" > pointcalc.1
groff -ww -man -Tutf8 -z pointcalc.1 2>groff.txt
expect_eq "$(cat groff.txt)" "" "groff -ww: no warnings"
run env MANWIDTH=100 man --warnings=w -l "$prefix/share/man/man1/pointcalc.1.gz"
expect_rc 0 "man -l"
expect_eq "$(cat err.txt)" "" "man -l: no warnings"
expect_in out.txt "pointcalc $version" "the man page's version is the program's"
cp out.txt man1.txt
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
for section in COMMANDS OPTIONS "REPL COMMANDS" ENVIRONMENT FILES "EXIT STATUS" EXAMPLES "SEE ALSO"; do
    checks=$((checks + 1))
    grep -q "^$section\$" man1.txt || fail "pointcalc(1) has no section $section"
done
for cmd in :help :show :save :load :clear :watch :quit; do
    checks=$((checks + 1))
    sed -n '/^REPL COMMANDS/,/^ENVIRONMENT/p' man1.txt | grep -q "^ *$cmd" || fail "pointcalc(1) lacks the REPL command $cmd"
done
for var in HOME NO_COLOR LUA_CPATH XDG_DATA_DIRS; do
    checks=$((checks + 1))
    sed -n '/^ENVIRONMENT/,/^EXIT/p' man1.txt | grep -q "$var" || fail "pointcalc(1)'s ENVIRONMENT lacks $var"
done

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
expect_eq "$(complete_words pointcalc --)" "$( (grep '^--' options.txt; echo --fps) | sort | tr '\n' ' ')" \
    "completion of --: every long option of --help, and --fps (named in --frames's text)"
expect_in options.txt "--emit-lua" "--help lists --emit-lua"
expect_eq "$(complete_words pointcalc -o '')" "c.png " "completion after -o: pictures"
expect_eq "$(complete_words pointcalc '')" "a.lua b.bas serve " "completion of the script: .lua and .bas, or serve"
# after the script: the options --help says may follow it (its "Options ... may also follow" line)
after=$(tr '\n' ' ' < help.txt | sed -n 's/.*Options \(.*\) may *also follow the script.*/\1/p' |
        grep -o -- '-[a-z-]*' | sort | tr '\n' ' ')
expect_in help.txt "--fps" "--help names --fps"
expect_eq "$(complete_words pointcalc a.lua -)" "$after" "completion after the script: $after"
checks=$((checks + 1))
case " $after" in *" --set "*) ;; *) fail "--help's list of options after the script lacks --set: $after" ;; esac
printf 'local k = slider("k", 0, 1, .5)\nlocal n = slider( "n", 1, 10, 3, 1)\n' > comp/a.lua
expect_eq "$(complete_words pointcalc a.lua --set '')" "k= n= " "--set offers the script's sliders"
expect_eq "$(complete_words pointcalc se)" "serve " "the command serve"
expect_eq "$(complete_words pointcalc serve '')" "a.lua b.bas " "serve takes a script"
expect_eq "$(complete_words pointcalc serve a.lua --)" "--port " "serve's --port"
expect_eq "$(complete_words pointcalc --fr)" "--frames " "--frames"
expect_eq "$(complete_words pointcalc --input '')" "a.lua b.bas c.png d.txt " "--input takes any file"
for opt in $(grep -- '^-' options.txt) --fps; do
    checks=$((checks + 1))
    case $opt in --) continue ;; esac
    [ "$(complete_words pointcalc "$opt")" = "$opt " ] ||
        [ -n "$(complete_words pointcalc "$opt" | grep -F -- "$opt ")" ] || fail "completion does not offer $opt"
done
# as a user's interactive bash finds it: bash-completion's loader, the prefix on XDG_DATA_DIRS
if [ -r /usr/share/bash-completion/bash_completion ]; then
    printf '. /usr/share/bash-completion/bash_completion\n' > "$WORK/bashrc"
    (cd comp && env -i HOME="$WORK" PATH="$prefix/bin:/usr/bin:/bin" XDG_DATA_DIRS="$prefix/share:/usr/share" \
        bash --rcfile "$WORK/bashrc" -i -c '__load_completion pointcalc || exit 3
            COMP_WORDS=(pointcalc --fp); COMP_CWORD=1; COMP_LINE="pointcalc --fp"; COMP_POINT=${#COMP_LINE}
            $(complete -p pointcalc | sed "s/.*-F \([^ ]*\).*/\1/")
            printf "%s\n" "${COMPREPLY[@]}"; compgen -W "$(complete -p pointcalc)" -- complete' \
        > "$WORK/bash_i.txt" 2>/dev/null)
    expect_eq "$(cat "$WORK/bash_i.txt")" "--fps
complete" "bash -i loads the completion from PREFIX/share/bash-completion"
else
    fail "bash-completion is not installed (setup.sh installs it)"
fi
# zsh's definition parses, and an interactive zsh completes with it (driven through zpty)
if command -v zsh >/dev/null; then
    run zsh -n "$prefix/share/zsh/site-functions/_pointcalc"
    expect_rc 0 "zsh -n _pointcalc: $(cat err.txt)"
    zsh_words() {  # the last line zsh shows after WORDS<Tab>
        env -i HOME="$WORK" TERM=dumb zsh -f "$PC_SOURCE_DIR/tests/cli/zsh_complete.zsh" \
            "$prefix/share/zsh/site-functions" "$prefix/bin" "$WORK/comp" "$1" 2>&1 |
            tr -d '\r' | sed 's/\x1b\[[0-9;?]*[a-zA-Z]//g' | tail -2 | tr '\n' ' '
    }
    out=$(zsh_words 'pointcalc --fr')
    checks=$((checks + 1)); case $out in *"pointcalc --frames"*) ;; *) fail "zsh: --fr<Tab>: $out" ;; esac
    out=$(zsh_words 'pointcalc -o ')
    checks=$((checks + 1)); case $out in *"pointcalc -o c.png"*) ;; *) fail "zsh: -o <Tab> offers pictures: $out" ;; esac
    out=$(zsh_words 'pointcalc a.lua --set ')
    checks=$((checks + 1)); case $out in *"k  n"*|*"k n"*) ;; *) fail "zsh: --set <Tab> offers the sliders: $out" ;; esac
else
    fail "zsh is not installed (setup.sh installs it)"
fi

# --- LuaRocks: the rockspec lints and `luarocks make` installs a working module ------------
rockspec=$PC_SOURCE_DIR/pointcalc-$version-1.rockspec
expect_file "$rockspec" "the rockspec's version is the program's"
expect_in "$rockspec" 'license = "MIT"' "the rockspec's licence"
expect_in "$PC_SOURCE_DIR/LICENSE" "MIT License" "LICENSE"
if ! command -v luarocks >/dev/null; then
    fail "luarocks is not installed (setup.sh installs it)"
else
    run luarocks lint "$rockspec"
    expect_rc 0 "luarocks lint: $(cat out.txt err.txt)"
    if [ "$PC_SANITIZE" = 1 ]; then
        echo "note: luarocks make is checked in the plain build, not under the sanitizers"
    else
        # the source tarball of ./build.sh dist, unpacked: luarocks builds in the folder it is run from
        mkdir distsrc && (cd "$PC_SOURCE_DIR" && tar --exclude=./build --exclude='./build-*' \
            --exclude=./.git --exclude=./gallery -cf - .) | (cd distsrc && tar -xf -)
        (cd distsrc && sh build.sh dist) > dist.txt 2>&1
        tarball=distsrc/build/pointcalc-$version.tar.gz
        expect_file "$tarball" "./build.sh dist: $(tail -3 dist.txt)"
        tar -xzf "$tarball"
        expect_file "pointcalc-$version/pointcalc-$version-1.rockspec" "the tarball holds the rockspec"
        expect_file "pointcalc-$version/LICENSE" "the tarball holds LICENSE"
        expect_no_file "pointcalc-$version/build" "the tarball holds no build"
        (cd "pointcalc-$version" && MAKEFLAGS=-j$(nproc) luarocks --lua-version 5.4 --tree "$WORK/tree" make \
            "pointcalc-$version-1.rockspec" >"$WORK/luarocks.log" 2>&1)
        rc=$?
        expect_rc 0 "luarocks make --tree: $(tail -5 luarocks.log)"
        expect_file tree/lib/lua/5.4/pointcalc.so "luarocks installed the module"
        run env LUA_CPATH="$WORK/tree/lib/lua/5.4/?.so" lua5.4 -e '
            local pc = require "pointcalc"; print(pc._VERSION, pc.dist(pc.P(0, 0), pc.P(3, 4)))'
        expect_eq "$(cat out.txt)" "$(printf 'pointcalc %s\t5.0' "$version")" "the rock's module works"
        run luarocks --lua-version 5.4 --tree "$WORK/tree" list --porcelain
        expect_in out.txt "pointcalc	$version-1	installed" "luarocks lists the rock"
        # luarocks pack: the source rock from the tarball (the rockspec dist writes beside it)
        (cd distsrc/build && luarocks --lua-version 5.4 pack "pointcalc-$version-1.rockspec") > pack.txt 2>&1
        rc=$?
        expect_rc 0 "luarocks pack: $(tail -3 pack.txt)"
        expect_file "distsrc/build/pointcalc-$version-1.src.rock" "the source rock"
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
    expect_eq "$(field Recommends)" "lua5.4, bash-completion" "Recommends"
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
    dpkg-deb -c "$deb" | awk '{ if ($(NF - 1) == "->") print $(NF - 2); else print $NF }' > contents.txt
    for f in usr/bin/pointcalc usr/lib/lua/5.4/pointcalc.so usr/share/man/man1/pointcalc.1.gz \
             usr/share/bash-completion/completions/pointcalc usr/share/doc/pointcalc/README.md \
             usr/share/doc/pointcalc/copyright usr/lib/libpointcalc.so.0 \
             usr/share/man/man7/pointcalc-api.7.gz usr/share/jupyter/kernels/pointcalc/kernel.json \
             usr/share/pointcalc/lua-language-server/library/globals.lua \
             "usr/$oval"; do
        expect_in contents.txt "./$f" "the package holds /$f"
    done
    expect_eq "$(grep -v '^\./usr/' contents.txt | grep -v '^\./$')" "" "nothing outside /usr"
    expect_eq "$(grep -c 'usr/include\|pkgconfig\|libpointcalc.so$' contents.txt)" "0" \
        "the development files are not in pointcalc but in pointcalc-dev"
    # pointcalc-dev: the headers, the pkg-config file, the link-time name; it needs pointcalc
    dev=$WORK/deb/pointcalc-dev_${version}_$arch.deb
    expect_file "$dev" "the -dev package"
    expect_eq "$(dpkg-deb -f "$dev" Depends)" "pointcalc (= $version)" "pointcalc-dev's Depends"
    expect_eq "$(dpkg-deb -f "$dev" Section)" "libdevel" "pointcalc-dev's Section"
    dpkg-deb -c "$dev" | awk '{ if ($(NF - 1) == "->") print $(NF - 2); else print $NF }' > dev.txt
    for f in usr/include/pointcalc/pointcalc.h usr/include/pointcalc/canvas.h usr/lib/pkgconfig/pointcalc.pc \
             usr/lib/libpointcalc.so usr/share/doc/pointcalc-dev/copyright \
             usr/share/doc/pointcalc-dev/examples/c/figure.c; do
        expect_in dev.txt "./$f" "pointcalc-dev holds /$f"
    done
    dpkg-deb -x "$deb" root
    use_tree "$WORK/root/usr" lib/lua/5.4 "unpacked .deb"
    # both packages unpacked: the example builds against them with pkg-config
    dpkg-deb -x "$dev" root
    (cd cprog && PKG_CONFIG_PATH="$WORK/root/usr/lib/pkgconfig" \
        sh -c 'cc figure.c $(pkg-config --cflags --libs pointcalc) -o figure2' >cc2.txt 2>&1)
    rc=$?
    expect_rc 0 "the example builds against the unpacked packages: $(head -3 cprog/cc2.txt)"
fi
finish
