' Defects found by fuzzing the front end, fixed: DATA +5 is the number 5; a variable whose
' Lua name is a translator helper's (gosub.10 next to GOSUB 10, SUB gosub.20) keeps both
' apart; a literal at the edge of SINGLE is still a number.
READ a, b: PRINT a; b
DATA +5, -7
gosub.10 = 5
GOSUB 10
PRINT gosub.10
CALL gosub.20
PRINT 3.402823E+38 > 1
END
10 PRINT "subroutine 10"
RETURN
SUB gosub.20
PRINT "SUB gosub.20"
END SUB
