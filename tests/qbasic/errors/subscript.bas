' EXPECT: 3: Subscript out of range
DIM a(5)
a(6) = 1
