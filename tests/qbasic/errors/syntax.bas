' EXPECT: 3: Syntax error
x = 1
y = 2 +
PRINT y
