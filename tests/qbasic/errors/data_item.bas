' EXPECT: 2: Syntax error
DATA 1, two
READ a, b: ' the bad item is reported on the DATA line
