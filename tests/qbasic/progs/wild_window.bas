' SCREEN 9 with WINDOW world coordinates, PMAP and SCREEN()
SCREEN 9
WINDOW (-2, -2)-(2, 2)
LINE (-2, 0)-(2, 0), 8
LINE (0, -2)-(0, 2), 8
FOR x = -2 TO 2 STEP .01
  PSET (x, x * x - 1), 11
NEXT
CIRCLE (0, 0), 1, 12
PRINT PMAP(0, 0); PMAP(0, 1); SCREEN(1, 1)
