' QBasic's RND: the same sequence on every run without RANDOMIZE
PRINT RND(1); RND(1); RND(1); RND(1); RND(1)
PRINT RND(0); RND
' RANDOMIZE n sets the middle 16 bits of the seed from n's DOUBLE bits (as QB64 reproduces QBasic)
RANDOMIZE 1: PRINT RND
PRINT RND(-1); RND(-1)
x = INT(RND * 6) + 1: PRINT x >= 1 AND x <= 6
