# compare_listing.sh SCRIPT: render a Stepanov example script and the cleaned QBasic listing it
# ports (through the QBasic front end) and compare them as line drawings: at least 95% of the
# ink of each must lie within 2 pixels of ink of the other.  Variant scripts (NNv_*.lua) have
# no listing: they must only run and draw.  Skipped (exit 77) without ../shared/listings.
: "${POINTCALC:?}" "${INKCMP:?}"
script=$1
name=$(basename "$script" .lua)
num=${name%%_*}                       # 02, 27b, 02v
listing="$PC_SHARED_DIR/listings/stepanov/ex$num.bas"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$POINTCALC" "$script" -o "$work/lua.ppm" || { echo "FAIL: $name does not run"; exit 1; }
case "$num" in
*v) echo "$name: a variant with no listing; it runs and draws"
    exec "$INKCMP" "$work/lua.ppm" "$work/lua.ppm" ;;
esac
if [ ! -f "$listing" ]; then
    echo "SKIP: $listing is absent (the listings live in ../shared beside the project)"
    exit 77
fi
"$POINTCALC" "$listing" -o "$work/bas.ppm" >/dev/null || { echo "FAIL: the listing ex$num.bas does not run"; exit 1; }
echo "$name vs ex$num.bas:"
"$INKCMP" "$work/lua.ppm" "$work/bas.ppm" 2 0.95
