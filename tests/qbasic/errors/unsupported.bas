' EXPECT: 3: CHAIN: not supported by pointcalc
SCREEN 12
CHAIN "next.bas"
