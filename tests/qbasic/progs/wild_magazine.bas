10 DEFSTR S: DEFINT I-N
20 S = "MAGAZINE": A! = 1.5: B# = 1# / 3: C& = 100000
30 ? S; A!; B#; C&
40 FOR I = 1 TO 3: ON I GOTO 50, 60, 70
50 ? "one";: GOTO 80
60 ? "two";: GOTO 80
70 ? "three";
80 NEXT I: ?
90 IF C& > 99999 THEN 100 ELSE 110
100 ? "big": GOTO 120
110 ? "small"
120 X = 0
130 WHILE X < 3: GOSUB 200: WEND
140 ? "x="; X: END
200 X = X + 1: ? X;: RETURN
