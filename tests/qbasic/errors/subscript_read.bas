' EXPECT: 4: Subscript out of range
DIM a(1 TO 3)
x = a(3)
x = a(0)
