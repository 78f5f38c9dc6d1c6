' EXPECT: 3: VARPTR of a simple variable or expression: not supported by pointcalc (of an element of a one-dimensional numeric array, or a string variable)
x = 5
PRINT VARPTR(x)
