DECLARE SUB walk (n)
walk 3
GOSUB sub1
PRINT "back"
n = 4
FOR i = 1 TO n STEP 2
  IF i = 1 THEN PRINT "first"; i: GOTO after
mid:
  PRINT "i"; i
NEXT
PRINT "out"; i
END
after:
GOTO mid
sub1:
  t = 0
  GOTO there
  DO WHILE t < 2
    t = t + 1
there:
    PRINT "t"; t
    IF t = 1 THEN EXIT DO
  LOOP
  PRINT "sub end"; t
RETURN
SUB walk (n)
  c = 0
  FOR k = n TO 2 * n
    IF k = n THEN
inner:
      PRINT "inner"; k; c
      c = c + 1
    END IF
    IF c = 1 THEN k = k + 1: GOTO inner
    IF c > 3 THEN EXIT SUB
  NEXT k
  PRINT "loop done"; k
END SUB
