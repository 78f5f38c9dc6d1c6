' EXPECT: 3: Illegal function call
x = -1
PRINT SQR(x)
