' A GOSUB target without RETURN: QBasic checks RETURN only when it runs, so the program runs,
' and the branch taken runs to the end of the program, which ends it.
10 FOR I = 1 TO 2
20 ON I GOSUB 100, 200
30 PRINT "back from"; I
40 NEXT
50 PRINT "not reached"
60 END
100 PRINT "subroutine 100": RETURN
200 PRINT "line 200 is the last line: the program ends here"
