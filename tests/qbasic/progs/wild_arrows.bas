' steer a dot with the arrow keys until Esc (NIBBLES style)
SCREEN 13
x = 160: y = 100
DO
  k$ = INKEY$
  SELECT CASE k$
    CASE CHR$(0) + "H": y = y - 1
    CASE CHR$(0) + "P": y = y + 1
    CASE CHR$(0) + "K": x = x - 1
    CASE CHR$(0) + "M": x = x + 1
    CASE CHR$(27): EXIT DO
  END SELECT
  PSET (x, y), 10
LOOP
PRINT x; y
