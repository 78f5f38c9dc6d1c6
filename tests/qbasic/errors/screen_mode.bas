' EXPECT: 2: SCREEN 9: not supported by pointcalc (SCREEN 12 and 13 are)
SCREEN 9
