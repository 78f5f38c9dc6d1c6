' The VGA hardware a program can see: the DAC palette through ports &H3C8/&H3C9 (written) and
' &H3C7/&H3C9 (read back), the retrace wait, the keyboard port &H60, video memory at &HA000 in
' SCREEN 13 and the BIOS data area (keyboard flags, video mode, timer ticks).
SCREEN 13
' DAC entry 40 is the default palette's pure red (63, 0, 0); entry 1 becomes orange
OUT &H3C7, 40: PRINT "DAC 40:"; INP(&H3C9); INP(&H3C9); INP(&H3C9)
OUT &H3C8, 1: OUT &H3C9, 63: OUT &H3C9, 32: OUT &H3C9, 0
' the write index moves on after each entry: two entries in a row (2 is dark blue, 3 green)
OUT &H3C9, 0: OUT &H3C9, 0: OUT &H3C9, 20: OUT &H3C9, 0: OUT &H3C9, 40: OUT &H3C9, 0
OUT &H3C7, 1
FOR i = 1 TO 9: PRINT INP(&H3C9);: NEXT: PRINT
LINE (0, 100)-(99, 119), 1, BF
LINE (100, 100)-(199, 119), 2, BF
LINE (200, 100)-(299, 119), 3, BF
' a palette animation waits for the vertical retrace: a tick of the virtual clock, no hang
FOR f = 1 TO 3: WAIT &H3DA, 8: WAIT &H3DA, 8, 8: NEXT
' video memory: a byte a pixel, 320 to a row
DEF SEG = &HA000
FOR x = 0 TO 49: POKE 320& * 150 + x, 40: NEXT
PRINT "pixel"; PEEK(320& * 110 + 50); POINT(10, 150); PEEK(320& * 150 + 10)
' the BIOS data area: video mode 13h, no shift keys down
DEF SEG = 0
PRINT "mode"; PEEK(&H449); "flags"; PEEK(&H417)
t0 = PEEK(&H46C): SLEEP 1: PRINT "ticks in a second:"; PEEK(&H46C) - t0
' the keyboard port: the scan code of each key of the input, then the last one released
DEF SEG
k$ = ""
FOR i = 1 TO 4: k$ = k$ + STR$(INP(&H60)): NEXT
PRINT "scan codes"; k$
