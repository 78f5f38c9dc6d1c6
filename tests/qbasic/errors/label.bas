' EXPECT: 2: Label not defined
GOTO 999
