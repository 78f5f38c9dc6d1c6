' EXPECT: 3: Label not defined
SUB s
  GOSUB 100
END SUB
100 PRINT "module"
RETURN
