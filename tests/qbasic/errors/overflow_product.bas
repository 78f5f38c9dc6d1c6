' EXPECT: 3: Overflow
' LONG products are checked as in QBasic: 65536& * 65536& must not wrap around (to 0 at the 4th power)
a& = 65536: PRINT a& * a& * a& * a&
