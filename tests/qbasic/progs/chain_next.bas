' The program chain.bas CHAINs to: its COMMON list takes chain.bas's values by position (run on
' its own, they are 0 and "").
COMMON n%, t$, s()
PRINT "in chain_next:"; n%; "["; t$; "]"; s(2)
IF n% > 0 THEN PRINT "the red box is still there:"; POINT(50, 50)
