' EXPECT: 2: COMMAND$ function: not supported by pointcalc
a$ = COMMAND$
