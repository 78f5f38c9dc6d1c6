' END inside a SUB ends the whole program normally; OPTION BASE 1 and variable bounds
OPTION BASE 1
n = 3: DIM a(n): a(1) = 10: a(3) = 30: PRINT LBOUND(a); UBOUND(a); a(1) + a(3)
PRINT "start"
CALL quit
PRINT "not reached"
SUB quit
  PRINT "quitting"
  END
END SUB
