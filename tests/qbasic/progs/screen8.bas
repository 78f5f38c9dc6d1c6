' SCREEN 8: EGA's 640x200 in 16 colours, 80x25 text in 8x8 cells, 4 pages; its pixels are
' 2.4 times as tall as wide on a 4:3 monitor, so CIRCLE's default aspect is 5/12
SCREEN 8
PRINT POINT(639, 199); POINT(640, 0); POINT(0, 200)
' pages 0-3: draw on page 3 while page 0 is shown, then copy it
SCREEN 8, , 3, 0
PSET (600, 150), 10
SCREEN 8, , 0, 0
PRINT POINT(600, 150);
PCOPY 3, 0
PRINT POINT(600, 150)
LINE (100, 60)-(139, 79), 12, BF
PRINT POINT(100, 60); POINT(139, 79); POINT(140, 79)
CIRCLE (320, 120), 100, 14
PRINT POINT(420, 120); POINT(320, 78); POINT(320, 162); POINT(320, 70)
' text cells of 8x8: row 25, columns 77-79 are y 192-199, x 608-631
LOCATE 25, 77: PRINT "END";
r = CSRLIN: c = POS(0)
LOCATE 5, 1: PRINT r; c
' COLOR takes a background (attribute 0 shown in blue), PALETTE colour numbers 0-15
COLOR 15, 1
PALETTE 12, 2
PRINT POINT(120, 70)
