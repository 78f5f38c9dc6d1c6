' single-line IF (everything after THEN up to ELSE is conditional), nested IF, block IF,
' IF ... GOTO, THEN/ELSE with line numbers, WHILE, DO in its four forms, EXIT FOR/DO
x = 5
IF x > 3 THEN PRINT "a";: PRINT "b" ELSE PRINT "c";: PRINT "d"
IF x < 3 THEN PRINT "a";: PRINT "b" ELSE PRINT "c";: PRINT "d"
IF x > 3 THEN IF x > 10 THEN PRINT "big" ELSE PRINT "mid"
IF x THEN PRINT "nonzero"
IF NOT x THEN PRINT "NOT 5 is -6, so true"
IF x = 5 AND x > 4 OR x < 0 THEN PRINT "and/or"
FOR i = 1 TO 4
  IF i = 1 THEN
    PRINT "one"
  ELSEIF i = 2 THEN
    PRINT "two"
  ELSE
    PRINT "many"; i
  END IF
NEXT
IF x > 3 GOTO 100
PRINT "skipped"
100 PRINT "jumped"
IF x = 5 THEN 200 ELSE 300
200 PRINT "two hundred": GOTO 400
300 PRINT "three hundred"
400 i = 0: WHILE i < 3: i = i + 1: WEND: PRINT i
i = 0: DO WHILE i < 3: i = i + 1: LOOP: PRINT i
i = 0: DO UNTIL i >= 3: i = i + 1: LOOP: PRINT i
i = 10: DO: i = i + 1: LOOP WHILE i < 3: PRINT i
i = 10: DO: i = i + 1: LOOP UNTIL i > 3: PRINT i
i = 0: DO: i = i + 1: IF i = 5 THEN EXIT DO
LOOP: PRINT i
FOR i = 1 TO 10: IF i = 4 THEN EXIT FOR
NEXT: PRINT i
FOR i = 1 TO 3: DO: EXIT FOR: LOOP: NEXT: PRINT i
' a backward GOTO inside a FOR body (the bisection loop of Example 30)
FOR c = 1 TO 2: x0 = -c: x1 = 0
1 x = (x0 + x1) / 2: IF x * x * x + x + c < 0 THEN x0 = x ELSE x1 = x
IF ABS(x1 - x0) > .001 THEN 1
PRINT CINT(x * 1000); : NEXT c: PRINT
ON 2 GOTO 500, 600
500 PRINT "five hundred"
600 PRINT "six hundred"
' leaving a FOR loop by GOTO; ON with an index past the list falls through
FOR i = 1 TO 10: IF i = 3 THEN GOTO 700
NEXT
700 PRINT "left the loop at"; i
ON 3 GOTO 500, 600: PRINT "fell through"
