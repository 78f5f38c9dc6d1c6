' DATA with labels, RESTORE label, quoted and unquoted strings
RESTORE colours
FOR i = 1 TO 3
  READ c$, r, g, b
  PRINT c$; r; g; b
NEXT
RESTORE numbers
READ a, b
PRINT a + b
END
colours:
DATA red, 63, 0, 0
DATA "green", 0, 63, 0, blue, 0, 0, 63
numbers:
DATA 1.5, 2.25
