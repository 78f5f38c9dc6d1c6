' EXPECT: 3: GOTO 110: jumps into a GOSUB subroutine or another procedure (line 6); pointcalc translates it only within one procedure, the main program or one subroutine
10 GOSUB 100
20 GOTO 110
30 END
100 PRINT "a"
110 PRINT "b"
120 RETURN
