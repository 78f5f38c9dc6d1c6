' EXPECT: 4: Syntax error (SAVE is a GW-BASIC command typed at the prompt, not a statement)
' in a program without line numbers SAVE is no statement
PRINT "drawn"
SAVE "PROG.BAS"
