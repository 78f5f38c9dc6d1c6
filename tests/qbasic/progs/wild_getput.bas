' a sprite kept with GET and put with PUT PSET, erased with PUT XOR
SCREEN 13
DIM sprite(100)
LINE (0, 0)-(9, 9), 4, BF
LINE (2, 2)-(7, 7), 15, BF
GET (0, 0)-(9, 9), sprite
CLS
FOR i = 0 TO 4
  PUT (50 + i * 20, 50), sprite, PSET
NEXT
PUT (50, 50), sprite, XOR
PRINT POINT(55, 55); POINT(75, 55); POINT(71, 51)
