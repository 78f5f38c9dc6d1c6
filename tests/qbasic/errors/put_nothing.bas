' EXPECT: 4: Illegal function call (PUT of an array element no GET stored a block in)
SCREEN 13
DIM a%(100)
PUT (10, 10), a%
