' a TIMER busy-wait and SLEEP (the virtual clock), CIRCLE in SCREEN 7
SCREEN 7
FOR i = 1 TO 5
  CIRCLE (160, 100), i * 15, i + 8
  t! = TIMER
  DO: LOOP WHILE TIMER < t! + .2
  SLEEP 1
NEXT
COLOR 15
LOCATE 1, 1: PRINT "5 rings"
