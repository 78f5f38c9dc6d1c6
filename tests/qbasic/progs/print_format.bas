' PRINT: leading space for non-negative numbers, a trailing space after every number,
' ";" joins, "," moves to the next 14-column zone, a trailing ";" keeps the line open
PRINT 1; -1; 0
PRINT .5; -.25; 1 / 3
PRINT 1E7; 1234567; 12345678; .0001; 1E-08; -1.5E+20
PRINT "a"; "b", "c"
PRINT 1, 2
PRINT "x";
PRINT "y"
PRINT 3.14159#; 1# / 3; 2 ^ .5
PRINT 100000 * 3; 32767 + 1
PRINT TAB(5); "t"; SPC(3); "s"
PRINT
PRINT "end"
