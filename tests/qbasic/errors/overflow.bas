' EXPECT: 2: Overflow
i% = 40000
