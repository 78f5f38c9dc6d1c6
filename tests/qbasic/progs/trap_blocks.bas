DECLARE FUNCTION inv! (x!)
ON ERROR GOTO handler
d = 0: stage = 1
10 IF 1 / d > 1 THEN PRINT "big" ELSE PRINT "small"
PRINT "after if": d = 0: stage = 0
20 WHILE 10 \ d > 0
  PRINT "in while"
WEND
PRINT "after while"
30 SELECT CASE LOG(d)
CASE IS > 0
  PRINT "positive"
CASE ELSE
  PRINT "else"
END SELECT
PRINT "after select"
40 FOR i = 1 TO inv(d)
  PRINT "i"; i
NEXT
PRINT "after for"; i
d = 0
DO
  d = d + 1
50 LOOP UNTIL inv(d - 1) > 0
PRINT "after do"; d
stage = 9
60 GOSUB deep
PRINT "not reached"
back:
PRINT "back from"; ERL
END
deep:
  FOR k = 1 TO 2
70  IF k = 2 THEN ERROR 11
  NEXT
RETURN
handler:
  PRINT "error"; ERR; "at"; ERL
  IF stage = 1 THEN d = 1: stage = 0: RESUME
  IF stage = 9 THEN RESUME back
  RESUME NEXT
FUNCTION inv (x)
  inv = 1 / x
END FUNCTION
