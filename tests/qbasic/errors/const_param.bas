' EXPECT: 3: Duplicate definition
CONST n = 3
SUB count (n)
  PRINT n
END SUB
