' EXPECT: 3: Path/File access error (/etc/passwd: a QBasic program reaches files in its folder and below only)
' a program reaches only its own folder and below
OPEN "/etc/passwd" FOR INPUT AS #1
