' EXPECT: 3: LOCATE: not supported by pointcalc
SCREEN 12
LOCATE 1, 1
