#!/bin/sh
# One entry point for building pointcalc:
#   ./build.sh            build (installs missing Debian packages first, see setup.sh)
#   ./build.sh gallery    build, then render every example into gallery/ (PNG, SVG, index.html)
#   ./build.sh test       build, then run the whole test suite
#   ./build.sh sanitize   build the tests under AddressSanitizer + UBSan in build-asan/ and run them
#   ./build.sh bench      build, then run the benchmarks in bench/
#   ./build.sh install [PREFIX]   install what build/ holds into PREFIX (default /usr/local): the
#                         program, libpointcalc with its headers and pkg-config file, the Lua
#                         module, the man pages, docs, examples, completion, editor definitions
#                         and the Jupyter kernel. Builds first only when there is no build/ (as
#                         the checkout's owner when run by root), so `sudo ./build.sh install`
#                         after your own build leaves nothing owned by root in the checkout.
#   ./build.sh uninstall [PREFIX] remove exactly what install put into PREFIX (from the manifest
#                         it left in PREFIX/share/pointcalc/install_manifest.txt)
#   ./build.sh dist       the source tarball build/pointcalc-VERSION.tar.gz (what the rockspec builds)
#                         and build/pointcalc-VERSION-1.rockspec that fetches it (for luarocks pack)
#   ./build.sh deb        build, then make the Debian packages build/pointcalc_VERSION_ARCH.deb and
#                         build/pointcalc-dev_VERSION_ARCH.deb (the C library's headers)
set -e
case "${2:-/usr/local}" in /*) prefix=${2:-/usr/local} ;; *) prefix="$(pwd)/$2" ;; esac   # for install
[ "$prefix" = / ] || prefix=${prefix%/}
cd "$(dirname "$0")"
jobs=$(nproc 2>/dev/null || echo 2)
manifest_rel=share/pointcalc/install_manifest.txt

build() {  # build DIR [cmake options...]
    ./setup.sh
    dir=$1; shift
    cmake -S . -B "$dir" "$@" >/dev/null
    if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
        cat "$dir/build.log" >&2
        exit 1
    fi
    grep -A3 'warning:' "$dir/build.log" >&2 || true   # the code is meant to build warning-free
}

# the checkout's owner, when root runs this in someone else's checkout: builds happen as them
owner=$(stat -c %u .)
as_owner() {
    if [ "$(id -u)" = 0 ] && [ "$owner" != 0 ]; then
        runuser -u "$(stat -c %U .)" -- "$@"
    else
        "$@"
    fi
}

install_tree() {
    if [ ! -f build/cmake_install.cmake ]; then
        as_owner ./build.sh build
    fi
    # the directories that exist before, so that uninstall removes only the ones it made
    before=$(mktemp)
    trap 'rm -f "$before"' EXIT
    [ -d "$prefix" ] && find "$prefix" -type d | sort > "$before"
    # cmake --install writes build/install_manifest.txt: give it back to the build's owner
    cmake --install build --prefix "$prefix"
    chown --reference=build build/install_manifest.txt 2>/dev/null || true
    mkdir -p "$prefix/share/pointcalc"
    files=$(mktemp)
    trap 'rm -f "$before" "$files"' EXIT
    { cat build/install_manifest.txt; echo; } | grep . > "$files"   # cmake ends it without a newline
    {
        sed 's/^/f /' "$files"
        echo "f $prefix/$manifest_rel"
        sed 's|/[^/]*$||' "$files" | sort -u | while read -r d; do
            while [ "${#d}" -gt "${#prefix}" ]; do echo "$d"; d=${d%/*}; done
        done | sort -u | comm -23 - "$before" | sed 's/^/d /'
    } > "$prefix/$manifest_rel"
    # the dynamic linker's cache, so that programs linked with -lpointcalc find the new library
    if [ "$(id -u)" = 0 ] && command -v ldconfig >/dev/null; then ldconfig || true; fi
    echo "installed into $prefix; './build.sh uninstall $prefix' removes it"
}

uninstall_tree() {
    m=$prefix/$manifest_rel
    if [ ! -f "$m" ]; then
        echo "uninstall: no $m: nothing of pointcalc is installed in $prefix" >&2
        exit 1
    fi
    list=$(mktemp)
    cp "$m" "$list"
    sed -n 's/^f //p' "$list" | while read -r f; do rm -f "$f"; done
    # the directories it made, deepest first, when nothing else has been put into them
    sed -n 's/^d //p' "$list" | sort -r | while read -r d; do rmdir "$d" 2>/dev/null || true; done
    rm -f "$list"
    if [ "$(id -u)" = 0 ] && command -v ldconfig >/dev/null; then ldconfig || true; fi
    echo "removed pointcalc from $prefix"
}

dist() {
    version=$(sed -n 's/^project(pointcalc VERSION \([^ )]*\).*/\1/p' CMakeLists.txt)
    mkdir -p build
    out=build/pointcalc-$version.tar.gz
    if git rev-parse --git-dir >/dev/null 2>&1; then
        # the committed tree plus uncommitted changes to tracked files (a work in progress)
        stash=$(git stash create)
        git archive --format=tar.gz --prefix="pointcalc-$version/" -o "$out" "${stash:-HEAD}"
    else
        tar --exclude=./build --exclude='./build-*' --exclude=./.git --exclude=./gallery -czf "$out" \
            --transform "s|^\.|pointcalc-$version|" .
    fi
    # the rockspec beside it, its source the tarball by absolute file:// address, so that
    # `luarocks pack build/pointcalc-VERSION-1.rockspec` makes the source rock from it
    sed "s|^   url = \"pointcalc-$version.tar.gz\"|   url = \"file://$(pwd)/$out\"|" \
        "pointcalc-$version-1.rockspec" > "build/pointcalc-$version-1.rockspec"
    echo "$out"
}

case "${1:-build}" in
build)     build build ;;
gallery)   build build && sh examples/render_gallery.sh build/pointcalc gallery ;;
test)      build build && ctest --test-dir build --output-on-failure -j "$jobs" ;;
sanitize)  build build-asan -DPC_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug &&
           ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
           LSAN_OPTIONS=suppressions="$(pwd)/tests/tools/lsan.supp" \
           ctest --test-dir build-asan --output-on-failure -j "$jobs" ;;
bench)     build build && sh bench/run.sh build/pointcalc ;;
install)   install_tree ;;
uninstall) uninstall_tree ;;
dist)      dist ;;
deb)       build build && (cd build && cpack -G DEB) ;;
*)         echo "usage: ./build.sh [build|gallery|test|sanitize|bench|install [PREFIX]|uninstall [PREFIX]|dist|deb]" >&2
           exit 2 ;;
esac
