' GOTO out of an error handler goes on there as RESUME line would; GOSUB into an IF block and
' its RETURN under ON ERROR (the module's GOSUBs kept in its code)
ON ERROR GOTO oops
FOR i = 1 TO 3
  IF i = 2 THEN
target:
    PRINT "target"; i
    IF called THEN called = 0: RETURN
  END IF
  GOSUB work
NEXT
PRINT "i"; i
ERROR 5
PRINT "not reached"
back:
PRINT "back"; ERR
END
work:
  PRINT "work"; 10 / (i - 1)
  IF i = 3 THEN called = 1: GOSUB target
  RETURN
oops:
  PRINT "oops"; ERR; ERL
  IF ERR = 5 THEN GOTO back
  RESUME NEXT
