' SELECT CASE: values, lists, ranges, IS comparisons, CASE ELSE, strings
FOR i = 0 TO 6
  SELECT CASE i
    CASE 0: PRINT "zero"
    CASE 1, 2: PRINT "one or two"
    CASE 3 TO 4: PRINT "three to four"
    CASE IS >= 6: PRINT "six or more"
    CASE ELSE: PRINT "else"; i
  END SELECT
NEXT
a$ = "b": SELECT CASE a$: CASE "a": PRINT "A": CASE "b", "c": PRINT "B or C": END SELECT
SELECT CASE .1: CASE .1: PRINT "SINGLE .1 matches": CASE ELSE: PRINT "no": END SELECT
