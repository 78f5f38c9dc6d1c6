' EXPECT: 3: Illegal function call
SCREEN 12
PAINT (10, 10), STRING$(65, 1)
