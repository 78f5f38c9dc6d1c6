' EXPECT: 3: Overflow
' a SINGLE result beyond 3.4E+38 is Overflow when printed, not "inf"
x = 1E+20: PRINT x * 1E+20
