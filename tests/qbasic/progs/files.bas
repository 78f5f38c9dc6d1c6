' Files in the program's folder: sequential (OUTPUT, APPEND, INPUT with EOF, INPUT #, LINE INPUT
' #, WRITE #), RANDOM records (TYPE variables and FIELD with LSET/RSET), BINARY bytes, LOF,
' SEEK, FREEFILE, NAME and KILL, and QBasic's errors trapped by number.
TYPE Rec
  id AS INTEGER
  nm AS STRING * 6
  v AS SINGLE
END TYPE
ON ERROR GOTO oops
f = FREEFILE
OPEN "seq.txt" FOR OUTPUT AS #f
PRINT #f, "alpha"; 12; "beta"
WRITE #f, "a, quoted", 3.5, -2
PRINT #f, "zone", "next"
CLOSE #f
OPEN "seq.txt" FOR APPEND AS #1: PRINT #1, "appended": CLOSE 1
OPEN "seq.txt" FOR INPUT AS #1
LINE INPUT #1, l$: PRINT "["; l$; "]"
INPUT #1, a$, x, y: PRINT "["; a$; "]"; x; y
DO WHILE NOT EOF(1): LINE INPUT #1, l$: PRINT "["; l$; "]": LOOP
PRINT "LOF"; LOF(1)
CLOSE
DIM r AS Rec
OPEN "recs.dat" FOR RANDOM AS #2 LEN = LEN(r)
FOR i = 1 TO 3
  r.id = i * 100: r.nm = "rec" + STR$(i): r.v = i / 4
  PUT #2, i, r
NEXT
GET #2, 2, r: PRINT r.id; "["; r.nm; "]"; r.v
PRINT "records"; LOF(2) \ LEN(r)
CLOSE #2
OPEN "field.dat" FOR RANDOM AS #3 LEN = 10
FIELD #3, 4 AS k$, 6 AS w$
LSET k$ = "ab": RSET w$ = "xyz": PUT #3, 1
LSET k$ = "": LSET w$ = "": GET #3, 1: PRINT "["; k$; "]["; w$; "]"
CLOSE #3
OPEN "bytes.bin" FOR BINARY AS #4
n% = 258: PUT #4, 1, n%: t$ = "QB": PUT #4, , t$
SEEK #4, 1: GET #4, , m%: PRINT m%; SEEK(4); LOF(4)
CLOSE #4
NAME "bytes.bin" AS "b2.bin"
KILL "b2.bin": KILL "recs.dat": KILL "field.dat": KILL "seq.txt"
OPEN "seq.txt" FOR INPUT AS #1
PRINT "not reached"
END
oops:
PRINT "error"; ERR
END
