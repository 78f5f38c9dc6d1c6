' EXPECT: 5: RESUME 20: pointcalc resumes only at a line at the top level of the program, not inside a block or subroutine
10 ON ERROR GOTO 100
15 FOR i = 1 TO 2
20 PRINT i: NEXT
100 RESUME 20
