' EXPECT: 3: RUN: not supported by pointcalc
SCREEN 12
RUN "next.bas"
