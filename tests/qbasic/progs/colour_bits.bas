' A colour beyond the mode's attributes keeps the bits its video memory has: 16 is 0 and 17 is 1
' in SCREEN 12, 7 is 3 in SCREEN 1; SCREEN 2 shows every colour but 0 as 1.
SCREEN 12
PSET (10, 10), 16: PSET (11, 10), 17: PSET (12, 10), 30
PRINT POINT(10, 10); POINT(11, 10); POINT(12, 10)
SCREEN 1
CIRCLE (160, 100), 50, 7
PRINT POINT(210, 100)
SCREEN 2
PSET (5, 5), 2: PSET (6, 5), 8
PRINT POINT(5, 5); POINT(6, 5)
