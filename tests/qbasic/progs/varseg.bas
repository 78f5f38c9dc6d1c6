' VARSEG, VARPTR and SADD in the emulated memory: an array's elements as QBasic stores them
' (INTEGER: 2 bytes, little-endian), reached by PEEK and POKE, saved and loaded by BSAVE and
' BLOAD; a string's characters through SADD
DIM a(1 TO 6) AS INTEGER, b(1 TO 6) AS INTEGER, s(2) AS SINGLE
FOR i = 1 TO 6: a(i) = i * 258 - 1000: NEXT
DEF SEG = VARSEG(a(1))
PRINT VARPTR(a(1)); VARPTR(a(3)); PEEK(VARPTR(a(3))); PEEK(VARPTR(a(3)) + 1); a(3)
POKE VARPTR(a(2)), 255: POKE VARPTR(a(2)) + 1, 127
PRINT a(2)
BSAVE "varseg.bin", VARPTR(a(1)), 12
DEF SEG = VARSEG(b(1))
BLOAD "varseg.bin", VARPTR(b(1))
FOR i = 1 TO 6: PRINT b(i); : NEXT: PRINT
' a SINGLE's four bytes: 1.5 is &H3FC00000
s(1) = 1.5
DEF SEG = VARSEG(s(0))
PRINT VARPTR(s(1)); PEEK(VARPTR(s(1)) + 2); PEEK(VARPTR(s(1)) + 3)
t$ = "QBasic"
DEF SEG = VARSEG(t$)
FOR i = 0 TO LEN(t$) - 1: PRINT CHR$(PEEK(SADD(t$) + i) + 1); : NEXT: PRINT
DEF SEG
KILL "varseg.bin"
