' TYPE records in an array, SWAP of records, REDIM clearing
TYPE Player
  nam AS STRING * 8
  score AS INTEGER
  x AS SINGLE
END TYPE
DIM p(1 TO 3) AS Player
p(1).nam = "Ann": p(1).score = 30
p(2).nam = "Bob": p(2).score = 10
p(3).nam = "Cy": p(3).score = 20
FOR i = 1 TO 2
  FOR j = i + 1 TO 3
    IF p(j).score > p(i).score THEN SWAP p(i), p(j)
  NEXT
NEXT
FOR i = 1 TO 3: PRINT RTRIM$(p(i).nam); p(i).score: NEXT
REDIM q(5)
q(5) = 7
REDIM q(10)
PRINT q(5); UBOUND(q)
