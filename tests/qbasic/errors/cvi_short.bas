' EXPECT: 3: Illegal function call
' CVI needs the 2 bytes of an INTEGER
PRINT CVI("A")
