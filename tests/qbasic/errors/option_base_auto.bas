' EXPECT: 4: Subscript out of range
' after OPTION BASE 1 an array used without DIM has subscripts 1..10
OPTION BASE 1
z(0) = 1
