' GOTO into blocks (QBasic allows it): a FOR body, IF and SELECT branches, DO and WHILE bodies
i = 5
GOTO inloop
FOR i = 1 TO 3
  PRINT "before"; i
inloop:
  PRINT "in"; i
NEXT i
PRINT "after"; i
x = 2
GOTO elsepart
IF x = 2 THEN
  PRINT "then"
ELSE
elsepart:
  PRINT "else"; x
END IF
SELECT CASE x
CASE 1
  PRINT "one"
incase:
  PRINT "case one tail"
CASE 2
  PRINT "two"
  IF n = 0 THEN n = 1: GOTO incase
END SELECT
k = 10
GOTO indo
DO
  k = k + 1
indo:
  PRINT "k"; k
LOOP UNTIL k >= 12
w = 0
GOTO inwhile
WHILE w < 3
  w = w + 1
inwhile:
  PRINT "w"; w
  IF w = 2 THEN e = 1
WEND
FOR j = 1 TO 10
  IF j = 3 THEN EXIT FOR
  IF j = 1 THEN GOTO inj
  PRINT "j"; j
inj:
NEXT j
PRINT "j after"; j
END
