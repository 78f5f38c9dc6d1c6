' A FUNCTION that assigns to its parameters changes the caller's variables, as QBasic passes
' arguments by reference (GORILLA.BAS's functions do this); an expression or (x) passes a copy.
FUNCTION Twice (v)
  v = v * 2: Twice = v
END FUNCTION
FUNCTION Bump% (a%, b%)
  a% = a% + 1: b% = b% + 10
  IF a% > 5 THEN EXIT FUNCTION
  Bump% = a% + b%
END FUNCTION
x = 1: PRINT Twice(x); x
PRINT Twice((x)); x
DIM n(3) AS INTEGER
i% = 2: n(2) = 4
PRINT Bump%(i%, n(2)); i%; n(2)
i% = 5: PRINT Bump%(i%, 7); i%
