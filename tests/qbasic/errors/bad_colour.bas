' EXPECT: 3: Illegal function call
SCREEN 12
CIRCLE (100, 100), 10, 256
