' Error trapping: ON ERROR GOTO, RESUME (the statement again), RESUME NEXT, RESUME line, ERR
' and ERL with QBasic's error numbers, ERROR n, an error in a SUB trapped at its CALL, and a
' GOSUB target without RETURN that ends the program when it runs.
10 ON ERROR GOTO 1000
20 d = 0: tries = 0
30 r = 10 / d: PRINT "10 /"; d; "="; r
40 PRINT "after RESUME:"; tries; "tries"
50 FOR i = -1 TO 1: PRINT SQR(i);: NEXT: PRINT
60 ERROR 53
70 ERROR 200
80 CALL Half(3)
90 PRINT "back after the CALL"
100 x$ = STRING$(2, 70000)
110 PRINT "not reached"
120 PRINT "resumed at 120"
130 DIM a(5): a(7) = 1
140 PRINT "never": END
1000 PRINT "error"; ERR; "in line"; ERL
1010 IF ERR = 11 AND ERL = 30 THEN tries = tries + 1: d = 2: RESUME
1020 IF ERR = 5 AND ERL = 100 THEN RESUME 120
1030 IF ERR = 9 THEN GOSUB 2000
1040 RESUME NEXT
2000 PRINT "subscript out of range: the end"
SUB Half (n)
  PRINT "in Half": q = n / 0
  PRINT "not reached in Half"
END SUB
