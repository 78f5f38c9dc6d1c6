#!/bin/sh
# A book's PDF atlas for the gallery (render_gallery.sh runs this where pointcalc writes PDF):
# every figure of the book in the print look, one per page in the gallery's order, each
# captioned in its bottom margin with its figure number and title. Ghostscript writes it.
#   sh gallery_atlas.sh OUTDIR GROUP LIST    LIST: lines "GROUP/NAME.pdf<TAB>caption"
#   writes OUTDIR/GROUP/atlas.pdf
set -e
out=$1 group=$2 list=$3
args="$out/$group/atlas.args"
# per page: the caption as a PostScript string in Latin-1 (the Times font's encoding), then the
# figure; EndPage writes the caption centred in the bottom margin (smaller when it is wider than
# the page)
: > "$args"
while IFS='	' read -r pdf caption; do
    [ -s "$out/$pdf" ] || continue
    text=$(printf '%s' "$caption" | iconv -f UTF-8 -t ISO-8859-1//TRANSLIT 2>/dev/null ||
           printf '%s' "$caption" | tr -cd '\11\12\15\40-\176')
    text=$(printf '%s' "$text" | sed 's/[\\()]/\\&/g')
    printf -- '-c\n/pc_caption (%s) def\n-f\n%s\n' "$text" "$out/$pdf" >> "$args"
done < "$list"
[ -s "$args" ] || { rm -f "$args"; exit 1; }
prolog='/pc_font /Times-Roman findfont dup length dict begin { 1 index /FID ne { def } { pop pop } ifelse } forall
/Encoding ISOLatin1Encoding def currentdict end definefont pop
<< /EndPage { exch pop 2 lt { gsave /pc_font findfont 9 scalefont setfont
   currentpagedevice /PageSize get 0 get /pc_pw exch def
   pc_caption stringwidth pop /pc_w exch def
   pc_w pc_pw 24 sub gt { /pc_font findfont 9 pc_pw 24 sub mul pc_w div scalefont setfont } if
   pc_pw pc_caption stringwidth pop sub 2 div 12 moveto
   pc_caption show grestore true } { false } ifelse } bind >> setpagedevice'
# one argument per line of $args (captions may hold spaces)
set --
while IFS= read -r a; do set -- "$@" "$a"; done < "$args"
gs -q -dNOPAUSE -dBATCH -dSAFER -sDEVICE=pdfwrite -sOutputFile="$out/$group/atlas.pdf" \
   -c "$prolog" "$@"
rm -f "$args"
