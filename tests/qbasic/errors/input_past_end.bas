' EXPECT: 5: Input past end of file
' reading past the last line
OPEN "past.txt" FOR OUTPUT AS #1: PRINT #1, "one": CLOSE #1
OPEN "past.txt" FOR INPUT AS #1: LINE INPUT #1, a$
LINE INPUT #1, a$
