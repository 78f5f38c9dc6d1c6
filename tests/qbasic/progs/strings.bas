' string basics for PRINT: + joins, LEN LEFT$ RIGHT$ MID$ STR$ VAL CHR$ ASC and friends
a$ = "Hello": b$ = a$ + ", world"
PRINT b$; LEN(b$)
PRINT LEFT$(b$, 4); "|"; RIGHT$(b$, 5); "|"; MID$(b$, 3, 4); "|"; MID$(b$, 8)
PRINT STR$(42); STR$(-1.5); VAL("3.5e2"); VAL(" 12abc"); VAL("x")
PRINT CHR$(65); ASC("a"); UCASE$("abc"); LCASE$("DEF")
PRINT INSTR(b$, "o"); INSTR(6, b$, "o"); HEX$(255); SPACE$(2); "|"; STRING$(3, "*"); STRING$(2, 66)
PRINT LTRIM$("  x"); RTRIM$("y  "); "|"; OCT$(8); HEX$(-1)
IF a$ < b$ THEN PRINT "shorter sorts first"
' VAL reads &H and &O as a program does: &HFFFF is the INTEGER -1, &HFFFF& the LONG 65535
PRINT VAL("&HFFFF"); VAL("&HFFFF&"); VAL("&h1F"); VAL("&H10000"); VAL("&O17"); VAL("&777")
