' A screen saver: it never ends by design (run it with --for SECONDS to see its picture); each
' frame waits for the retrace and a tick of TIMER.  Without --for it ends here when the
' virtual clock passes a minute, so that the test suite can run it too.
SCREEN 13
x = 10: dx = 3
DO
  CIRCLE (x, 100), 8, 0
  x = x + dx: IF x > 310 OR x < 10 THEN dx = -dx
  CIRCLE (x, 100), 8, 14
  PSET (x, 150), 1 + (x MOD 15)
  WAIT &H3DA, 8
  t = TIMER: WHILE TIMER = t: WEND
  IF TIMER > 60 THEN EXIT DO
LOOP
PRINT "a minute of frames: x ="; x
