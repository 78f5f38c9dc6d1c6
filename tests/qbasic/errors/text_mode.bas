' EXPECT: 3: Illegal function call
' graphics before SCREEN 12 (Example 1 as printed)
PSET (1, 1)
