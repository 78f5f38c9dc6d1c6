#!/bin/sh
# One entry point for building pointcalc:
#   ./build.sh            build (installs missing Debian packages first, see setup.sh)
#   ./build.sh gallery    build, then render every example into gallery/ (PNG, SVG, index.html)
#   ./build.sh test       build, then run the whole test suite
#   ./build.sh sanitize   build the tests under AddressSanitizer + UBSan in build-asan/ and run them
#   ./build.sh bench      build, then run the benchmarks in bench/
#   ./build.sh install [PREFIX]   build, then install into PREFIX (default /usr/local): the
#                         program, the Lua module, the man page, docs, examples, bash completion
#   ./build.sh deb        build, then make the Debian package build/pointcalc_VERSION_ARCH.deb
set -e
case "${2:-/usr/local}" in /*) prefix=${2:-/usr/local} ;; *) prefix="$(pwd)/$2" ;; esac   # for install
cd "$(dirname "$0")"
./setup.sh
jobs=$(nproc 2>/dev/null || echo 2)

build() {  # build DIR [cmake options...]
    dir=$1; shift
    cmake -S . -B "$dir" "$@" >/dev/null
    if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
        cat "$dir/build.log" >&2
        exit 1
    fi
    grep -A3 'warning:' "$dir/build.log" >&2 || true   # the code is meant to build warning-free
}

case "${1:-build}" in
build)    build build ;;
gallery)  build build && sh examples/render_gallery.sh build/pointcalc gallery ;;
test)     build build && ctest --test-dir build --output-on-failure -j "$jobs" ;;
sanitize) build build-asan -DPC_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug &&
          ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
          LSAN_OPTIONS=suppressions="$(pwd)/tests/tools/lsan.supp" \
          ctest --test-dir build-asan --output-on-failure -j "$jobs" ;;
bench)    build build && sh bench/run.sh build/pointcalc ;;
install)  build build && cmake --install build --prefix "$prefix" ;;
deb)      build build && (cd build && cpack -G DEB) ;;
*)        echo "usage: ./build.sh [build|gallery|test|sanitize|bench|install [PREFIX]|deb]" >&2; exit 2 ;;
esac
