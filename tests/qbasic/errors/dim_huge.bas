' EXPECT: 2: Out of memory
DIM a(32767, 32767)
PRINT "never"
