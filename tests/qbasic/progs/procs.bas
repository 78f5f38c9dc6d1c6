' SUB and FUNCTION with parameters (a SUB changes its caller's variables), recursion,
' DEF FN (single and multi-line), DIM SHARED, CONST, GOSUB/RETURN with numbers and labels
DECLARE SUB swapit (a, b)
DECLARE FUNCTION fact# (n%)
CONST twopi = 6.2831853#, n = 3
DEF FNsq (x) = x * x
DEF FNmax (a, b)
  IF a > b THEN FNmax = a ELSE FNmax = b
END DEF
DIM SHARED total
x = 1: y = 2
CALL swapit(x, y): PRINT x; y
swapit x, y: PRINT x; y
DIM arr(3): arr(2) = 5: swapit arr(2), x: PRINT arr(2); x
PRINT fact#(10); FNsq(3); FNmax(2, 7); FNmax(9, 7)
addto 5: addto 7: PRINT total
PRINT twopi; n
fill arr(): PRINT arr(0); arr(3)
GOSUB 100: PRINT "back"
FOR i = 1 TO 2: GOSUB show: NEXT
ON 2 GOSUB 100, show
END
100 PRINT "in 100"
RETURN
show: PRINT "show"; i
RETURN
SUB swapit (a, b)
  t = a: a = b: b = t
END SUB
FUNCTION fact# (k%)
  IF k% <= 1 THEN fact# = 1 ELSE fact# = k% * fact#(k% - 1)
END FUNCTION
SUB addto (v)
  total = total + v
END SUB
SUB fill (w())
  FOR i = LBOUND(w) TO UBOUND(w): w(i) = i * n: NEXT
END SUB
