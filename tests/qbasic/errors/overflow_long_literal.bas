' EXPECT: 2: Overflow
x = 1E19&
