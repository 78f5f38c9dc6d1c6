' EXPECT: 4: POKE &H1000:&H0 into a string: not supported by pointcalc
t$ = "abc"
DEF SEG = VARSEG(t$)
POKE SADD(t$), 65
