#!/bin/sh
# The gallery's PDF atlas per book (examples/gallery_atlas.sh): where the program writes PDF
# (the print renderer), render_gallery.sh puts every figure of a book in the print look into
# GROUP/atlas.pdf, one page per figure, captioned with its figure number and title, and links
# it from the contents. Skipped (77) while the program refuses -o x.pdf.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
if ! "$POINTCALC" -e 'pset(0, 0)' -o probe.pdf >/dev/null 2>&1 || [ ! -s probe.pdf ]; then
    echo "skip: this pointcalc does not write PDF (-o x.pdf), so there is no atlas"
    exit 77
fi
for tool in gs pdfinfo pdftotext; do
    command -v $tool >/dev/null || { fail "$tool is missing (setup.sh installs ghostscript, poppler-utils)"; finish; exit 1; }
done
run sh "$PC_SOURCE_DIR/examples/render_gallery.sh" "$POINTCALC" gallery
expect_rc 0 "render_gallery.sh"
for dir in "$PC_SOURCE_DIR"/examples/*/; do
    group=$(basename "$dir")
    ls "$dir"*.lua >/dev/null 2>&1 || continue
    n=$(ls "$dir"*.lua | wc -l)
    atlas=gallery/$group/atlas.pdf
    expect_file "$atlas" "the atlas of $group"
    expect_eq "$(pdfinfo "$atlas" | sed -n 's/^Pages: *//p')" "$n" "$group's atlas has a page per figure"
    expect_in gallery/index.html "<a href=\"$group/atlas.pdf\">PDF atlas</a>" "the contents link $group's atlas"
done
pdftotext gallery/stepanov/atlas.pdf stepanov.txt
expect_in stepanov.txt "example 2: Example 2" "Stepanov's example 2 captioned with its number"
pdftotext gallery/basics/atlas.pdf basics.txt
expect_in basics.txt "2.8.4, Fig. 2.12: A cube in isometric projection" \
    "a figure after the textbook captioned with its section and figure number"
pdftotext gallery/buimov/atlas.pdf buimov.txt
expect_in buimov.txt "3.2, Fig. 3.1: A circle from a point" "a Buimov figure captioned with its section and figure number"
finish
