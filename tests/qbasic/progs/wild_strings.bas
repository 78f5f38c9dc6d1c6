' MID$ assignment, INSTR from a position, VAL of hex, INPUT$ from the keyboard
a$ = "The quick brown fox"
MID$(a$, 5, 5) = "QUICK"
PRINT a$; INSTR(6, a$, "o"); LCASE$(a$)
PRINT STRING$(3, 65); STR$(-3.5); VAL("&H1F"); VAL("  12abc")
FOR i = 1 TO 3: b$ = b$ + CHR$(64 + i): NEXT: PRINT b$
k$ = INPUT$(3)
PRINT "["; k$; "]"
PRINT LEN(DATE$); LEN(TIME$)
