' EXPECT: 2: FUNCTION twice assigns to its parameter v: pass the argument as (x) (by value); pointcalc does not pass FUNCTION arguments by reference
x = 1: PRINT twice(x)
FUNCTION twice (v)
  v = v * 2: twice = v
END FUNCTION
