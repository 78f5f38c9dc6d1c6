' EXPECT: 2: INKEY$ function: not supported by pointcalc
k$ = INKEY$
