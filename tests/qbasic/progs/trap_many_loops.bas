' 130 FOR loops with computed bounds under ON ERROR: more loop locals than Lua allows in a function
ON ERROR GOTO h
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 2
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 3
FOR i = 1 TO n STEP n
  s = s + i
NEXT
n = 1
FOR i = 1 TO n STEP n
  s = s + i
NEXT
PRINT s
END
h: PRINT "err"; ERR: RESUME NEXT
