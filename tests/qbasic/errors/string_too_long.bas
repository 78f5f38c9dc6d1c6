' EXPECT: 4: String formula too complex
a$ = SPACE$(20000)
PRINT LEN(a$)
b$ = a$ + a$
