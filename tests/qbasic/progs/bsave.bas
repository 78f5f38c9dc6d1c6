' BSAVE and BLOAD of a SCREEN 13 picture: the video memory at &HA000 to a file of QBasic's
' format (a 7-byte header, then the bytes) and back, after CLS
SCREEN 13
CIRCLE (160, 100), 60, 14: PAINT (160, 100), 1, 14
DEF SEG = &HA000
BSAVE "picture.bin", 0, 64000
OPEN "picture.bin" FOR BINARY AS #1
h$ = SPACE$(7): GET #1, 1, h$
PRINT "header:"; ASC(h$); CVI(MID$(h$, 2, 2)); CVI(MID$(h$, 4, 2)); CVI(MID$(h$, 6, 2)); "size"; LOF(1)
CLOSE #1
CLS
PRINT "after CLS"; POINT(160, 100)
BLOAD "picture.bin"
PRINT "after BLOAD"; POINT(160, 100); POINT(100, 100); POINT(5, 199)
KILL "picture.bin"
