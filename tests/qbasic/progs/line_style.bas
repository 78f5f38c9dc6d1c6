' LINE's style: 16 bits, the high bit first, repeated along the line (in boxes too); &HFF00 is
' 8 pixels on, 8 off.  POINT reads them back.
SCREEN 12
LINE (0, 10)-(47, 10), 15, , &HFF00
LINE (0, 20)-(31, 20), 14, , &HAAAA
LINE (100, 100)-(131, 131), 12, B, &HF0F0
LINE -(163, 131), 10, , &HFF00
FOR x = 0 TO 47: a$ = a$ + CHR$(48 + SGN(POINT(x, 10))): NEXT: PRINT a$
FOR x = 0 TO 15: b$ = b$ + CHR$(48 + SGN(POINT(x, 20))): NEXT: PRINT b$
FOR x = 100 TO 115: c$ = c$ + CHR$(48 + SGN(POINT(x, 100))): NEXT: PRINT c$
FOR x = 131 TO 146: d$ = d$ + CHR$(48 + SGN(POINT(x, 131))): NEXT: PRINT d$
