' EXPECT: 4: Out of DATA
DATA 1, 2
READ a, b
READ c
