' text mode: COLOR, LOCATE, CSRLIN/POS, VIEW PRINT and the string functions
CLS
COLOR 14, 1
LOCATE 5, 10: PRINT "Menu";
PRINT CSRLIN; POS(0)
VIEW PRINT 10 TO 20
LOCATE 12, 1
PRINT "in view"
PRINT STRING$(5, "*"); SPACE$(3); "|"
a$ = "Hello, World"
PRINT LEFT$(a$, 5); "-"; RIGHT$(a$, 5); "-"; MID$(a$, 8, 3); LEN(a$); INSTR(a$, "o"); UCASE$(a$)
PRINT LTRIM$("  x"); RTRIM$("y  "); "|"; STR$(42); VAL("3.5e2"); HEX$(255); OCT$(8); CHR$(65); ASC("a")
VIEW PRINT
