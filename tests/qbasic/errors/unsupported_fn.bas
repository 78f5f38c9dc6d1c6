' EXPECT: 2: DATE$ function: not supported by pointcalc
d$ = DATE$
