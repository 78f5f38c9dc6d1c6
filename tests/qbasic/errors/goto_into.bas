' EXPECT: 2: GOTO 10: jumps into a block or another procedure (line 4); pointcalc translates GOTO only to a label in the same or an enclosing block
GOTO 10
FOR i = 1 TO 3
10 PRINT i
NEXT
