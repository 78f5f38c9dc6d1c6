' the numeric functions, in SINGLE (7 digits) unless given a DOUBLE
LET pi = 4 * ATN(1)
PRINT pi; 4 * ATN(1#); SIN(pi / 6); COS(0); TAN(pi / 4)
PRINT EXP(1); LOG(EXP(2)); SQR(2); SQR(2#)
PRINT INT(2.7); INT(-2.7); FIX(2.7); FIX(-2.7); SGN(0); SGN(3.5); ABS(-3)
PRINT CINT(-3.5); CLNG(123456.5); CSNG(1 / 3#); CDBL(.5)
t = TIMER: PRINT t >= 0 AND t < 86400
PRINT "stop here"
STOP
PRINT "not reached"
