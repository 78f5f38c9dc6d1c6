' EXPECT: 4: Statement illegal in TYPE block
TYPE Cell
  v AS INTEGER
  PRINT v
END TYPE
