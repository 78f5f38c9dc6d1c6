' CHAIN runs another program of the folder (.BAS by default), which gets the variables of
' COMMON by position; the screen stays as it is.  chain_next.bas is the other program.
COMMON SHARED count%, title$, scores()
DIM scores(3)
count% = 3: title$ = "from chain.bas": scores(2) = 42
SCREEN 13
LINE (0, 0)-(99, 99), 4, BF
PRINT "chaining"
CHAIN "chain_next"
PRINT "not reached: CHAIN does not come back"
