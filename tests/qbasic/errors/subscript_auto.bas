' EXPECT: 2: Subscript out of range
y = sqrt(11): ' SQRT is not a QBasic function: an array of 0..10 (Example 26 as printed)
