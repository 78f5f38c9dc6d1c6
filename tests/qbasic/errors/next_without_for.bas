' EXPECT: 3: NEXT without FOR
FOR i = 1 TO 3
NEXT j
