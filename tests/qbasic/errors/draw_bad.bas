' EXPECT: 3: Illegal function call (draw: unknown command 'Q' at character 5)
SCREEN 12
DRAW "R10 Q5"
