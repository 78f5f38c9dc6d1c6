' TYPE ... END TYPE: a polygon as an array of records, a label in a fixed-length string
TYPE Vertex
  x AS SINGLE
  y AS SINGLE
END TYPE
TYPE Shape
  tag AS STRING * 8
  corners AS INTEGER
  centre AS Vertex
END TYPE
DECLARE SUB Move (s AS Shape, dx!, dy!)
DIM tri(1 TO 3) AS Vertex
DIM sh AS Shape, copy AS Shape
FOR i = 1 TO 3
  READ tri(i).x, tri(i).y
NEXT i
DATA 100, 50, 200, 150, 20, 150
sh.tag = "triangle shape"
sh.corners = 3
FOR i = 1 TO 3
  sh.centre.x = sh.centre.x + tri(i).x / 3
  sh.centre.y = sh.centre.y + tri(i).y / 3
NEXT i
PRINT "["; sh.tag; "]"; LEN(sh.tag); sh.corners
PRINT "centre"; sh.centre.x; sh.centre.y
copy = sh
Move sh, 10, -5
PRINT "moved"; sh.centre.x; sh.centre.y; "copy"; copy.centre.x; copy.centre.y
copy.tag = "tri"
PRINT "["; copy.tag; "]"; ASC(RIGHT$(copy.tag, 1))
SCREEN 12
FOR i = 1 TO 3
  j = i MOD 3 + 1
  LINE (tri(i).x, tri(i).y)-(tri(j).x, tri(j).y), 14
NEXT i
PSET (sh.centre.x, sh.centre.y), 12
PRINT POINT(100, 50); POINT(150, 150); POINT(sh.centre.x, sh.centre.y)

SUB Move (s AS Shape, dx!, dy!)
  s.centre.x = s.centre.x + dx!
  s.centre.y = s.centre.y + dy!
END SUB
