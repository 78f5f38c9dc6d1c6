' COLOR fg, bg, border in text mode: the border is the screen's overscan, outside any picture;
' QBasic checks it is a colour 0..15.  Then a graphics screen, where COLOR has no border.
COLOR 14, 1, 4
PRINT "text mode, border 4"
COLOR 7, 0, 0
SCREEN 12
COLOR 10
PSET (5, 5)
PRINT "point"; POINT(5, 5)
