' STATIC variables in a FUNCTION and a STATIC SUB, DIM SHARED
DECLARE FUNCTION Counter% ()
DECLARE SUB Bump ()
DIM SHARED total
FOR i = 1 TO 3: PRINT Counter%; : NEXT
PRINT
Bump: Bump
PRINT total
FUNCTION Counter%
  STATIC n AS INTEGER
  n = n + 1
  Counter% = n
END FUNCTION
SUB Bump STATIC
  k = k + 10
  total = total + k
END SUB
