' EXPECT: 3: Overflow
' string lengths and counts are INTEGERs (strings have at most 32767 characters)
PRINT LEN(SPACE$(2000000000))
