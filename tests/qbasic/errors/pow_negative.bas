' EXPECT: 2: Illegal function call
x = -8: y = x ^ (1 / 3)
