' EXPECT: 9: Subscript out of range
OPTION BASE 1
DIM m(3, 4), v(-5 TO 5)
PRINT LBOUND(m, 1); UBOUND(m, 2); LBOUND(v); UBOUND(v)
FOR i = 1 TO 3: FOR j = 1 TO 4: m(i, j) = i * j: NEXT j, i
PRINT m(3, 4); m(2, 3)
ERASE m
PRINT m(3, 4)
v(6) = 1
