' EXPECT: 6: Element not defined
TYPE Pair
  a AS INTEGER
END TYPE
DIM p AS Pair
p.b = 1
