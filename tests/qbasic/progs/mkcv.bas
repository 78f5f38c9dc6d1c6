' Numbers as the bytes QBasic stores them: MKI$, MKL$, MKS$ (IEEE single, rounded as QBasic
' rounds a SINGLE), MKD$ and back with CVI, CVL, CVS, CVD; LSET and RSET in a string's length.
DEFINT I
FUNCTION Bytes$ (s$)
  FOR i = 1 TO LEN(s$): t$ = t$ + RIGHT$("0" + HEX$(ASC(MID$(s$, i, 1))), 2) + " ": NEXT
  Bytes$ = t$
END FUNCTION
PRINT "MKI$(-2)    "; Bytes$(MKI$(-2)); CVI(MKI$(-2))
PRINT "MKI$(258)   "; Bytes$(MKI$(258)); CVI(CHR$(2) + CHR$(1))
PRINT "MKL$(-65536) "; Bytes$(MKL$(-65536)); CVL(MKL$(-65536))
PRINT "MKS$(1.5)   "; Bytes$(MKS$(1.5)); CVS(MKS$(1.5))
PRINT "MKS$(.1)    "; Bytes$(MKS$(.1)); CVS(MKS$(.1))
PRINT "MKD$(.1#)   "; Bytes$(MKD$(.1#)); CVD(MKD$(.1#))
a$ = SPACE$(6): b$ = "xxxxxx"
LSET a$ = "ab": RSET b$ = "cd"
PRINT "["; a$; "] ["; b$; "]"
LSET a$ = "too long for it": PRINT "["; a$; "]"
DIM f AS STRING * 4
RSET f = "z": PRINT "["; f; "]"
