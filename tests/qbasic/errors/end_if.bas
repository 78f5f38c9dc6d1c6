' EXPECT: 2: Block IF without END IF
IF x THEN
PRINT 1
