' EXPECT: 4: Illegal function call
SCREEN 12
DIM a%(1)
GET (0, 0)-(10, 10), a%
