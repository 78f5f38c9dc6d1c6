' EXPECT: 2: Label not defined
GOTO inside
END
SUB s
inside:
END SUB
