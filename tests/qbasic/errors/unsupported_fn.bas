' EXPECT: 2: STICK function: not supported by pointcalc
x = STICK(0)
