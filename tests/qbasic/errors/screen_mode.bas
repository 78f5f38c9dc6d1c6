' EXPECT: 3: SCREEN 8: not supported by pointcalc (SCREEN 1, 2, 7, 9, 11, 12 and 13 are)
PRINT "refused before the program runs: this line never prints"
SCREEN 8
