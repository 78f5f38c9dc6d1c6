' GET and PUT with every action: a 4x3 sprite of colour 5 with a dot of 9, copied with PSET,
' XOR twice over a coloured box (which restores the box), PRESET (the complement), AND, OR;
' the array must hold what QBasic's GET stores (4 + 4 planes * 1 byte * 3 rows = 16 bytes).
SCREEN 12
DIM sprite%(7)
LINE (10, 300)-(13, 302), 5, BF: PSET (11, 301), 9
GET (10, 300)-(13, 302), sprite%
PUT (100, 300), sprite%, PSET
PRINT POINT(100, 300); POINT(101, 301); POINT(104, 300)
LINE (200, 300)-(220, 320), 3, BF
PUT (202, 302), sprite%
PRINT POINT(202, 302); POINT(203, 303)
PUT (202, 302), sprite%, XOR
n = 0
FOR y = 300 TO 320: FOR x = 200 TO 220
  IF POINT(x, y) = 3 THEN n = n + 1
NEXT x, y
PRINT "box pixels after XOR twice:"; n
PUT (300, 300), sprite%, PRESET
PRINT POINT(300, 300); POINT(301, 301)
LINE (400, 300)-(410, 310), 6, BF
PUT (400, 300), sprite%, AND
PUT (405, 305), sprite%, OR
PRINT POINT(400, 300); POINT(406, 306)
' two sprites in one array: GET into an element, PUT from it
DIM two%(20)
GET (10, 300)-(11, 301), two%(10)
PUT (500, 300), two%(10), PSET
PRINT POINT(500, 300); POINT(501, 301)
