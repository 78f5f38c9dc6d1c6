' EXPECT: 4: Bad file mode
' PRINT # to a file opened for INPUT
OPEN "file_mode.txt" FOR OUTPUT AS #1: CLOSE #1: OPEN "file_mode.txt" FOR INPUT AS #1
PRINT #1, "x"
