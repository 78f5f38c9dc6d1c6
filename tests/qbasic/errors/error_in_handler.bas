' EXPECT: 7: Division by zero
' an error inside the error handler is not trapped: it ends the program
ON ERROR GOTO handler
ERROR 5
END
handler:
x = 1 / 0
RESUME NEXT
