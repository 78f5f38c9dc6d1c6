' EXPECT: 3: Syntax error
' line numbers are 0..65529 (a bigger one was an internal error of the translator)
1E51 PRINT 1
