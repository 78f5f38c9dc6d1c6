' EXPECT: 3: CALL ABSOLUTE: not supported by pointcalc (it runs x86 machine code from memory, and pointcalc emulates no processor)
DIM code%(20)
CALL ABSOLUTE(VARPTR(code%(0)))
