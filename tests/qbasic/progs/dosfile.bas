' A DOS file: CR LF line ends and the end-of-file byte Ctrl-Z, where QBasic stops reading
10 PRINT "line"; 10
20 FOR I = 1 TO 3: PRINT I;: NEXT: PRINT
30 PRINT "last line before Ctrl-Z"
this is not BASIC: garbage after the end of the file
