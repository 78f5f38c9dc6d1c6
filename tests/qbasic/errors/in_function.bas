' EXPECT: 5: Illegal function call
PRINT root(-4)
END
FUNCTION root (v)
  root = SQR(v)
END FUNCTION
