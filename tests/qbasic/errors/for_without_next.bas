' EXPECT: 2: FOR without NEXT
FOR i = 1 TO 3
PRINT i
