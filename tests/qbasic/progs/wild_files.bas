' sequential files: OUTPUT, APPEND, INPUT with EOF and LINE INPUT #, WRITE #, KILL
OPEN "scores.txt" FOR OUTPUT AS #1
PRINT #1, "Ann"; 30
WRITE #1, "Bob", 20
CLOSE #1
OPEN "scores.txt" FOR APPEND AS #1
PRINT #1, "Cy 10"
CLOSE
OPEN "scores.txt" FOR INPUT AS #2
DO WHILE NOT EOF(2)
  LINE INPUT #2, l$
  PRINT "["; l$; "]"
LOOP
CLOSE #2
KILL "scores.txt"
