' The SCREEN(row, col) function: the code of the character at a text position (32 where
' nothing was printed), in text mode and on a graphics screen; CLS empties the screen.
PRINT "Hello"
LOCATE 3, 10: PRINT "QB";
a = SCREEN(1, 1): b = SCREEN(3, 11): c = SCREEN(2, 5)
PRINT : PRINT a; b; c
SCREEN 12
LOCATE 5, 20: PRINT "x";
d = SCREEN(5, 20): CLS: e = SCREEN(5, 20)
PRINT d; e; SCREEN(1, 1, 1)
