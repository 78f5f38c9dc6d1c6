' PRINT # USING formats into a file; INPUT$(n, #f) reads bytes of a file (sequential or binary)
OPEN "using.txt" FOR OUTPUT AS #1
PRINT #1, USING "##.## & #"; 3.14159; "pi"; 7
PRINT #1, USING "$$#,###"; 1234;
PRINT #1, "!"
CLOSE #1
OPEN "using.txt" FOR INPUT AS #1
PRINT "["; INPUT$(9, #1); "]"; LOF(1)
LINE INPUT #1, rest$: PRINT "["; rest$; "]"
LINE INPUT #1, l$: PRINT "["; l$; "]"
CLOSE #1
OPEN "using.txt" FOR BINARY AS #2
SEEK #2, 3: PRINT "["; INPUT$(4, 2); "]"
CLOSE #2
KILL "using.txt"
