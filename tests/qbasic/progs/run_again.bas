' RUN starts the program again with its variables cleared (here until the input answers N);
' the file it reads counts the runs.
IF runs = 0 THEN PRINT "a fresh start: runs ="; runs
OPEN "runs.txt" FOR APPEND AS #1: PRINT #1, "run": CLOSE #1
OPEN "runs.txt" FOR INPUT AS #1
DO WHILE NOT EOF(1): LINE INPUT #1, l$: n = n + 1: LOOP
CLOSE #1
PRINT "run number"; n
runs = n
INPUT "Again"; a$
IF UCASE$(a$) = "Y" THEN RUN
KILL "runs.txt"
PRINT "done after"; runs; "runs"
