' EXPECT: 3: OPEN: not supported by pointcalc
SCREEN 12
OPEN "scores.txt" FOR OUTPUT AS #1
