' EXPECT: 3: GOTO inh: jumps into the error handler (line 6): not supported by pointcalc
ON ERROR GOTO h
GOTO inh
END
h: PRINT "h"
inh: PRINT "in"
RESUME NEXT
