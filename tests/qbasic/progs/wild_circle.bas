' CIRCLE arcs (negative angles draw the radii) and an ellipse by aspect; an arc to about pi/2
' (PI = 3.14159) lights its last pixel, the top one (320, 140)
SCREEN 12
CONST PI = 3.14159
CIRCLE (320, 240), 100, 14, 0, PI / 2
CIRCLE (320, 240), 100, 12, -PI, -3 * PI / 2
CIRCLE (100, 100), 50, 10, , , .5
PRINT POINT(420, 240); POINT(320, 140); POINT(220, 240); POINT(100, 75)
