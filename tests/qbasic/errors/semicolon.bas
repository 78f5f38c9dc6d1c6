' EXPECT: 2: Syntax error
xa = 1; ya = 2: ' ';' is not a statement separator (the defect of Examples 10, 14, 18)
