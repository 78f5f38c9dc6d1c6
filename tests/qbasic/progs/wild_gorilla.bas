DECLARE FUNCTION Clamp! (v!, lo!, hi!)
' a FUNCTION that assigns to its own parameter
angle = 45: speed = 200
PRINT Clamp(angle, 0, 30); angle
PRINT Clamp(speed, 0, 100)
FUNCTION Clamp! (v!, lo!, hi!)
  IF v! < lo! THEN v! = lo!
  IF v! > hi! THEN v! = hi!
  Clamp! = v!
END FUNCTION
