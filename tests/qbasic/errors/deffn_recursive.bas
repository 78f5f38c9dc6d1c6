' EXPECT: 2: Out of stack space
DEF FNa(x) = FNa(x) + 1
PRINT FNa(1)
