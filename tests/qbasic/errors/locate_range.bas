' EXPECT: 3: Illegal function call
SCREEN 12
LOCATE 31, 1
