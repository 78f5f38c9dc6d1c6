' EXPECT: 7: Division by zero
' a runtime error inside a SUB names the SUB's line
CALL f(0)
END
SUB f (d)
  x = 1
  PRINT x / d
END SUB
