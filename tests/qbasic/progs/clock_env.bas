' TIME$ and DATE$ on the virtual clock (settable), ENVIRON$ empty, CLEAR resetting the module's
' variables but not its CONSTs, and PALETTE USING.
CONST limit = 3
PRINT TIME$; " "; DATE$
SLEEP 61: PRINT TIME$
TIME$ = "23:59:58": PRINT TIME$; TIMER
DATE$ = "12-24-1989": PRINT DATE$
DATE$ = "7/4/99": PRINT DATE$
PRINT "["; ENVIRON$("PATH"); "]"; LEN(ENVIRON$(1))
a = 5: b$ = "text": DIM c(3): c(2) = 7
CLEAR
PRINT a; "["; b$; "]"; c(2); limit
SCREEN 12
DIM p(15) AS LONG
FOR i = 0 TO 15: p(i) = -1: NEXT
p(1) = 63: p(2) = 63 * 256
PALETTE USING p(0)
LINE (0, 100)-(99, 119), 1, BF
LINE (100, 100)-(199, 119), 2, BF
LINE (200, 100)-(299, 119), 4, BF
