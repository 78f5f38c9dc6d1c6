#!/bin/sh
# The include rule of DESIGN.md's layout: the kernel (stdlib/geom) includes nothing from the
# books (stdlib/books), the books nothing from the bindings, and only the bindings
# (stdlib/lua) and the host (interp) include Lua's headers.
set -e
cd "${PC_SOURCE_DIR:?}"
fail=0
book_headers=$(cd stdlib/books && ls */*.h | sed 's#.*/##')
for h in $book_headers; do
    if grep -l "#include \"$h\"" stdlib/geom/*.c stdlib/geom/*.h stdlib/draw/*.c stdlib/draw/*.h 2>/dev/null; then
        echo "layout: the kernel or draw/ includes the book header $h" >&2; fail=1
    fi
done
for f in $(grep -l '#include <\(lua\|lauxlib\|lualib\)\.h>' -r stdlib interp tests 2>/dev/null || true); do
    case $f in stdlib/lua/*|interp/*|tests/fuzz/*) ;; *) echo "layout: $f includes a Lua header" >&2; fail=1 ;; esac
done
for f in stdlib/geom/*; do
    case $(basename "$f") in *konop*|*buimov*|*korotky*|*stepanov*|*ferguson*|*elastic*|*conic*|*qbnum*)
        echo "layout: $f is named after a book's construction; it belongs in stdlib/books" >&2; fail=1 ;; esac
done
for a in stepanov konopatsky buimov korotky; do
    [ -d "stdlib/books/$a" ] || { echo "layout: stdlib/books/$a is missing" >&2; fail=1; }
    [ -d "tests/books/$a" ] || { echo "layout: tests/books/$a is missing" >&2; fail=1; }
done
exit $fail
