' CHR$(0) on a graphics screen is a blank cell, as on QBasic's screen (no glyph)
SCREEN 12
PRINT "A"; CHR$(0); "B"
FOR y = 0 TO 15: FOR x = 0 TO 23
  IF POINT(x, y) THEN lit(x \ 8) = lit(x \ 8) + 1
NEXT x, y
PRINT "lit pixels in the cells of A, CHR$(0), B:"; lit(0); lit(1); lit(2)
