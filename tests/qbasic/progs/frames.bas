' An animation for --frames: a red square moves 20 pixels a second of the virtual clock (SLEEP 1
' is one), so with --frames N --fps 1 frame k shows it at x = 20 * (k + 1)
SCREEN 13
FOR i = 1 TO 10
  LINE (x, 50)-(x + 9, 59), 0, BF
  x = 20 * i
  LINE (x, 50)-(x + 9, 59), 12, BF
  SLEEP 1
NEXT
PRINT "x ="; x
