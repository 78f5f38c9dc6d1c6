' EXPECT: 4: RESUME without error
' RESUME reached without an error being handled
PRINT "start"
RESUME NEXT
