' EXPECT: 2: Type mismatch
a$ = 5
