' EXPECT: 3: File not found
' OPEN FOR INPUT of a file that is not there
OPEN "no-such-file.txt" FOR INPUT AS #1
