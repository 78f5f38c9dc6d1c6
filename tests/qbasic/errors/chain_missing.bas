' EXPECT: 3: File not found
' CHAIN to a program that is not in the folder
CHAIN "nothere"
