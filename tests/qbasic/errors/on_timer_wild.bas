' EXPECT: 2: ON TIMER: not supported by pointcalc
ON TIMER(1) GOSUB tick
TIMER ON
DO: LOOP UNTIL INKEY$ <> ""
END
tick: PRINT "tick": RETURN
