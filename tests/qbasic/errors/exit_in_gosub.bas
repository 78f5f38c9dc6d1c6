' EXPECT: 7: EXIT SUB inside a GOSUB subroutine: not supported by pointcalc
SUB s
  GOSUB 10
  PRINT "back"
  EXIT SUB
10 PRINT "in"
  EXIT SUB
  RETURN
END SUB
