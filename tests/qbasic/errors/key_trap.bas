' EXPECT: 2: KEY(n) trapping: not supported by pointcalc
KEY(1) ON
ON KEY(1) GOSUB help
PRINT "ok"
END
help: PRINT "help": RETURN
