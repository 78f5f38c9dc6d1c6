' EXPECT: 4: Illegal function call
a$ = "abc"
MID$(a$, 3) = "Z": PRINT a$
MID$(a$, 4) = "Z"
