' EXPECT: 2: Illegal outside of SUB, FUNCTION or DEF FN
STATIC n
