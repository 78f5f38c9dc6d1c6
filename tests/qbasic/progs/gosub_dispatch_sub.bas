' a SUB whose GOTOs leave its GOSUB subroutine and whose GOSUBs go into a FOR body and an IF block
DECLARE SUB menu (n)
menu 3
menu 0
SUB menu (n)
  c = 0
  GOSUB show
  IF n = 0 THEN GOTO done
  FOR i = 1 TO n
    IF i = 2 THEN GOSUB inloop
  NEXT
  PRINT "c"; c
  EXIT SUB
show:
  PRINT "show"; n
  IF n = 0 THEN GOTO done
  RETURN
done:
  PRINT "done"
  IF c = 0 THEN c = 1: GOSUB inloop2
  EXIT SUB
  FOR j = 1 TO 2
inloop2:
    PRINT "inloop2"
    RETURN
  NEXT
  IF n THEN
inloop:
    c = c + 10
    RETURN
  END IF
END SUB
