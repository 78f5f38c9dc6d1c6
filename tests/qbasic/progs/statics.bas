' STATIC, ERASE, the MID$ statement, GOSUB inside a SUB, fixed-length strings
DECLARE SUB Tally (v)
DECLARE FUNCTION NextId% ()
DECLARE SUB Frame (w%)
FOR k = 1 TO 4: Tally k * k: NEXT k
PRINT NextId%; NextId%; NextId%
DIM score(1 TO 4), names$(1 TO 2)
score(2) = 7: score(4) = 9: names$(1) = "Ada"
ERASE score, names$
PRINT score(2); score(4); "["; names$(1); "]"
w$ = "QBASIC 4.5"
MID$(w$, 8) = "1.1"
PRINT w$
MID$(w$, 1, 2) = "qbxx"
PRINT w$
DIM cell AS STRING * 4
PRINT LEN(cell); ASC(cell)
cell = "ab"
PRINT "["; cell; "]"
cell = "abcdefg"
PRINT "["; cell; "]"
Frame 6
long$ = STRING$(16000, "x")
long$ = long$ + long$
PRINT LEN(long$)

SUB Frame (w%)
  GOSUB edge
  PRINT "|"; SPACE$(w%); "|"
  GOSUB edge
  EXIT SUB
edge:
  PRINT "+"; STRING$(w%, "-"); "+"
  RETURN
END SUB

FUNCTION NextId% STATIC
  id% = id% + 1
  NextId% = id%
END FUNCTION

SUB Tally (v)
  STATIC n, sum, hist$
  n = n + 1
  sum = sum + v
  hist$ = hist$ + LTRIM$(STR$(v)) + " "
  PRINT n; sum; hist$
END SUB
