' EXPECT: 2: Division by zero
PRINT 5 MOD 0
