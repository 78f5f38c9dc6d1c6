' EXPECT: 2: Overflow
IF 5 < 1E39 THEN PRINT "then" ELSE PRINT "else"
