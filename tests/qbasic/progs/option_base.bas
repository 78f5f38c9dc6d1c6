' OPTION BASE 1: DIM a(n) has subscripts 1..n, and an array used without DIM has 1..10, in the
' module and in a SUB (a(0) is then "Subscript out of range": errors/option_base*.bas)
OPTION BASE 1
DIM a(3): a(1) = 5
z(10) = 7
PRINT LBOUND(a); UBOUND(a); a(1); LBOUND(z); UBOUND(z); z(10)
CALL s
SUB s
  w(1) = 2: PRINT LBOUND(w); UBOUND(w); w(1)
END SUB
