' FOR accumulates in the variable's precision (SINGLE): the counts of stepanov_examples.md §F
FOR t = 0 TO 1 STEP .001: n = n + 1: NEXT t
PRINT n; t
n = 0: FOR t = 0 TO 1 STEP .0001: n = n + 1: last = t: NEXT
PRINT n; last
n = 0: FOR r = .2 TO 1.6 STEP .2: n = n + 1: NEXT: PRINT n; r
n = 0: FOR r = .2 TO 1.8 STEP .2: n = n + 1: NEXT: PRINT n
n = 0: FOR t = -1 TO 0 STEP .01: n = n + 1: NEXT: PRINT n
n = 0: FOR p = -5 TO 5 STEP .01: n = n + 1: NEXT: PRINT n
n = 0: pi = 4 * ATN(1): FOR u = 0 TO 2 * pi STEP pi / 50000: n = n + 1: NEXT: PRINT n; pi
n = 0: FOR r = 0 TO .95 STEP .05: n = n + 1: NEXT: PRINT n
' a DOUBLE loop with the SINGLE constant .1 as step: .1000000014901161 per pass
n = 0: FOR x# = 0 TO 1 STEP .1: n = n + 1: NEXT: PRINT n
' integers, negative steps, zero passes, the value after the loop, changing the variable
FOR i = 1 TO 10: NEXT: PRINT i
FOR i = 10 TO 1 STEP -3: PRINT i;: NEXT: PRINT i
FOR i = 5 TO 1: PRINT "never": NEXT: PRINT i
FOR i = 1 TO 10: i = i + 1: PRINT i;: NEXT: PRINT
FOR i% = 1 TO 3: PRINT i%;: NEXT i%: PRINT i%
k = 3: FOR i = 1 TO k: k = 10: NEXT: PRINT i
FOR i = 1 TO 3: FOR j = 1 TO 2: PRINT i * 10 + j;: NEXT j, i: PRINT
FOR i = 1 TO 2: FOR j = 1 TO 2: NEXT: NEXT: PRINT i; j
s = .5: FOR i = 0 TO 2 STEP s: PRINT i;: NEXT: PRINT
