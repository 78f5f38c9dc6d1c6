' bouncing ball drawn with PSET and erased with PRESET, SCREEN 13
SCREEN 13
x = 160: y = 100: dx = 3: dy = 2
FOR frame = 1 TO 50
  FOR a = 0 TO 6.28 STEP .1
    PSET (x + 5 * COS(a), y + 5 * SIN(a)), 14
  NEXT
  IF x + dx > 310 OR x + dx < 10 THEN dx = -dx
  IF y + dy > 190 OR y + dy < 10 THEN dy = -dy
  IF frame < 50 THEN
    FOR a = 0 TO 6.28 STEP .1
      PRESET (x + 5 * COS(a), y + 5 * SIN(a))
    NEXT
  END IF
  x = x + dx: y = y + dy
NEXT
PRINT x; y
