' EXPECT: 6: Type mismatch
TYPE Pair
  a AS INTEGER
END TYPE
DIM p AS Pair
p = 5
