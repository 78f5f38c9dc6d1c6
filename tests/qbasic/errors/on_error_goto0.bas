' EXPECT: 4: Subscript out of range
' ON ERROR GOTO 0 in the handler: the error it handles ends the program, named at its line
ON ERROR GOTO handler
DIM a(3): a(4) = 1
END
handler:
IF ERR = 9 THEN ON ERROR GOTO 0
RESUME NEXT
