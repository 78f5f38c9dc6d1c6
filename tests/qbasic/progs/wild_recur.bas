' recursion (factorial, Fibonacci, Hanoi), integer division and MOD, PRINT USING
DECLARE FUNCTION Fact# (n%)
DECLARE FUNCTION Fib& (n%)
DECLARE SUB Hanoi (n%, a$, b$, c$)
DIM SHARED moves%
PRINT Fact#(10); Fib&(20)
Hanoi 4, "A", "B", "C"
PRINT "moves"; moves%
PRINT 17 \ 5; 17 MOD 5; -17 \ 5; -17 MOD 5; 2 ^ 10; 7 / 2
PRINT USING "##.##  $$###.##  +#.#^^^^"; 3.14159; 42.5; 12345
FUNCTION Fact# (n%)
  IF n% <= 1 THEN Fact# = 1 ELSE Fact# = n% * Fact#(n% - 1)
END FUNCTION
FUNCTION Fib& (n%)
  IF n% < 2 THEN Fib& = n%: EXIT FUNCTION
  Fib& = Fib&(n% - 1) + Fib&(n% - 2)
END FUNCTION
SUB Hanoi (n%, a$, b$, c$)
  IF n% = 0 THEN EXIT SUB
  Hanoi n% - 1, a$, c$, b$
  moves% = moves% + 1
  Hanoi n% - 1, c$, b$, a$
END SUB
