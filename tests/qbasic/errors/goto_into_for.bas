' EXPECT: 6: NEXT without FOR
n = 3
GOTO body
FOR i = 1 TO n
body:
NEXT
