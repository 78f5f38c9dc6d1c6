' EXPECT: 3: Division by zero
x = 0
PRINT 1 / x
