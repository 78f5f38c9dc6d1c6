' SORTDEMO's kind: a bubble sort in a SUB over an INTEGER array, bars drawn with LINE BF
DEFINT A-Z
DECLARE SUB BubbleSort (a() AS INTEGER, n AS INTEGER)
DECLARE SUB ShowBars (a() AS INTEGER, n AS INTEGER)
CONST NMAX = 20
DIM SHARED Swaps AS LONG
DIM a(1 TO NMAX) AS INTEGER
RANDOMIZE 1
FOR i = 1 TO NMAX: a(i) = INT(RND * 100) + 1: NEXT
SCREEN 12
BubbleSort a(), NMAX
ShowBars a(), NMAX
PRINT "swaps:"; Swaps
FOR i = 1 TO NMAX - 1
  IF a(i) > a(i + 1) THEN PRINT "unsorted"
NEXT
SUB BubbleSort (a() AS INTEGER, n AS INTEGER)
  DO
    switched = 0
    FOR i = 1 TO n - 1
      IF a(i) > a(i + 1) THEN SWAP a(i), a(i + 1): switched = 1: Swaps = Swaps + 1
    NEXT
  LOOP WHILE switched
END SUB
SUB ShowBars (a() AS INTEGER, n AS INTEGER)
  FOR i = 1 TO n
    LINE (0, 20 + i * 10)-(a(i) * 5, 27 + i * 10), (i MOD 15) + 1, BF
  NEXT
END SUB
