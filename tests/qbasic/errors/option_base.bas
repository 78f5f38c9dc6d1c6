' EXPECT: 3: Subscript out of range
OPTION BASE 1: DIM a(3)
a(0) = 1
