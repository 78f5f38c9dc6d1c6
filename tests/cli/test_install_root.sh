#!/bin/sh
# `sudo ./build.sh install` after a user's own build (issue 27): a throwaway user builds a copy
# of the checkout, root installs it into a prefix with build.sh, and the checkout stays the
# user's (nothing owned by root, the user's build and package step still work); then
# `./build.sh uninstall` leaves the prefix exactly as it was. Needs root (runuser, useradd).
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
if [ "$(id -u)" != 0 ] || ! command -v runuser >/dev/null || ! command -v useradd >/dev/null; then
    echo "skip: needs root, runuser and useradd"
    exit 77
fi
if [ "$PC_SANITIZE" = 1 ]; then
    echo "skip: the install as root is checked with the plain build"
    exit 77
fi
user=pcinst$$
useradd --no-create-home --shell /bin/sh "$user" || { echo "skip: useradd failed"; exit 77; }
trap 'userdel "$user" 2>/dev/null; rm -rf "$WORK"' EXIT
chmod 755 "$WORK"
as_user() { runuser -u "$user" -- "$@"; }

# the user's checkout and build (only what installing needs: the unit tests are not built)
mkdir src && (cd "$PC_SOURCE_DIR" && tar --exclude=./build --exclude='./build-*' --exclude=./.git --exclude=./gallery -cf - .) |
    (cd src && tar -xf -)
chown -R "$user" src
(cd src && as_user cmake -S . -B build -DCMAKE_BUILD_TYPE=Debug >"$WORK/cmake.log" 2>&1 &&
    as_user cmake --build build -j2 --target install_deps >>"$WORK/cmake.log" 2>&1)
rc=$?
expect_rc 0 "the user's build: $(tail -5 cmake.log)"

# a prefix that already holds something of its own: uninstall must leave it as it was
prefix=$WORK/prefix
mkdir -p "$prefix/bin" "$prefix/share/man/man1" "$prefix/share/keep"
echo mine > "$prefix/bin/other-tool"
(cd "$prefix" && find . | sort) > before.txt

run sh src/build.sh install "$prefix"
expect_rc 0 "sudo ./build.sh install PREFIX after the user's build: $(tail -3 err.txt)"
expect_in out.txt "installed into $prefix" "install says where"
expect_eq "$(find src ! -user "$user" | head -5)" "" "nothing in the checkout is owned by root"
expect_file "$prefix/bin/pointcalc" "the program installed"
expect_file "$prefix/share/pointcalc/install_manifest.txt" "the manifest in the prefix"
run "$prefix/bin/pointcalc" -e 'print(dist(P(0, 0), P(3, 4)))'
expect_eq "$(cat out.txt)" "5.0" "the installed program runs (libpointcalc through its RUNPATH)"

# the user goes on working: rebuild, a test, the package step that a root-owned build/ broke
(cd src && as_user cmake --build build -j2 --target install_deps) >build2.log 2>&1
rc=$?
expect_rc 0 "the user's rebuild after the root install: $(tail -3 build2.log)"
# the user's tests of the program (those the partial build has: the Lua-level ones) write into
# build/ and pass
(cd src && as_user ctest --test-dir build -R '^lua/' -j2) >ctest.log 2>&1
rc=$?
expect_rc 0 "the user's ctest after the root install: $(grep -E 'tests passed|Failed' ctest.log | head -3)"
expect_in ctest.log "100% tests passed" "every Lua-level test passes for the user"
(cd src && as_user cpack -G DEB --config build/CPackConfig.cmake -B "$WORK/src/build/deb") >cpack.log 2>&1
rc=$?
expect_rc 0 "the user's cpack after the root install: $(grep -i error cpack.log | head -3)"

# uninstall: exactly what was installed goes, the prefix's own files and folders stay
run sh src/build.sh uninstall "$prefix"
expect_rc 0 "./build.sh uninstall PREFIX: $(cat err.txt)"
(cd "$prefix" && find . | sort) > after.txt
expect_eq "$(diff before.txt after.txt)" "" "uninstall leaves the prefix as it was"
run sh src/build.sh uninstall "$prefix"
expect_rc 1 "a second uninstall"
expect_in err.txt "nothing of pointcalc is installed in $prefix" "a second uninstall says why"
expect_eq "$(find src ! -user "$user" | head -5)" "" "the checkout is still the user's"
finish
