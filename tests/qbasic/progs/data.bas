' DATA anywhere, one read pointer through all items in order; an unquoted ':' ends DATA;
' RESTORE to the start or to a label; READ into arrays
DATA 1, 2.5, "hello, world", -3
READ a, b, c$, d
PRINT a; b; c$; d
DATA .25:REM a comment, not an item
READ e: PRINT e
RESTORE: READ f: PRINT f
RESTORE 20: READ g, h$: PRINT g; h$
DIM v(2): FOR i = 0 TO 2: READ v(i): NEXT: PRINT v(0) + v(1) + v(2)
20 DATA 99, abc def
DATA 1,2,3
' READ s$ of a numeric item gets its text as written; an empty item is 0 or ""
READ s$, t$, u$, n, w$: PRINT "["; s$; "]["; t$; "]["; u$; "]"; n; "["; w$; "]"
DATA 007, 1.50, 3.5E2, ,
