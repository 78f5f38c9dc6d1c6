' EXIT SUB and EXIT FUNCTION inside a GOSUB subroutine of the procedure (QBasic leaves the
' procedure, its GOSUBs with it)
DECLARE SUB walk (n)
DECLARE FUNCTION first% (limit%)
walk 2
walk 5
PRINT first%(3); first%(50)
SUB walk (n)
  FOR i = 1 TO n
    GOSUB stepit
  NEXT
  PRINT "walked"; n
  EXIT SUB
stepit:
  PRINT i;
  IF i = 3 THEN PRINT "stop": EXIT SUB
  RETURN
END SUB
FUNCTION first% (limit%)
  k% = 0
again:
  GOSUB try
  GOTO again
try:
  k% = k% + 7
  IF k% > limit% THEN first% = k%: EXIT FUNCTION
  RETURN
END FUNCTION
