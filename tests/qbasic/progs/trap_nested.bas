ON ERROR GOTO handler
FOR i = 1 TO 5
  FOR j = 1 TO 3
    IF j = 2 THEN EXIT FOR
    PRINT i; j;
  NEXT j
  IF i = 1 THEN
    PRINT "one"
  ELSEIF i = 2 THEN
    GOSUB two
  ELSEIF 1 / (i - 3) THEN
    PRINT "elseif"
  ELSE
    PRINT "else"
  END IF
  SELECT CASE i
  CASE ELSE
    PRINT "any"
  END SELECT
  DO
    IF i = 4 THEN EXIT DO
    EXIT DO
  LOOP
  IF i = 4 THEN EXIT FOR
NEXT i
PRINT "i ="; i
END
two:
  PRINT "two"
  RETURN
handler:
  PRINT "handler"; ERR
  RESUME NEXT
