' Text on the graphics screen: PRINT at LOCATE 1, 1 puts the glyph of the 8x16 font in the
' top-left cell (shown below as # for ink, . for paper), COLOR sets the ink, CSRLIN and POS
' follow the cursor, a PRINT past the right edge wraps.
SCREEN 12
LOCATE 1, 1: COLOR 14: PRINT "A";
r = CSRLIN: c = POS(0)
COLOR 15
LOCATE 3, 1
FOR y = 0 TO 15
  row$ = ""
  FOR x = 0 TO 7
    IF POINT(x, y) = 14 THEN row$ = row$ + "#" ELSE row$ = row$ + "."
  NEXT x
  PRINT row$
NEXT y
PRINT "cursor after A:"; r; c
LOCATE 25, 78: PRINT "wrap";
PRINT " row"; CSRLIN; "col"; POS(0)
' SCREEN 13: 8x8 cells, 40 columns
SCREEN 13
LOCATE 2, 40: PRINT "Z";
PRINT " row"; CSRLIN
n = 0
FOR y = 8 TO 15: FOR x = 312 TO 319: IF POINT(x, y) = 15 THEN n = n + 1
NEXT x, y
PRINT "ink pixels of Z in the 8x8 cell at row 2, column 40:"; n
