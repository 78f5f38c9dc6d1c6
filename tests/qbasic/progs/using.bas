' PRINT USING: a shop's price list and the format characters one by one
CLS
PRINT USING "###.##"; 3.5
PRINT USING "###.##"; -3.5
PRINT USING "#.##"; .5
PRINT USING ".##"; .25
PRINT USING "+##.#"; 7.26; -7.26
PRINT USING "##.#-"; 7.26; -7.26
PRINT USING "**###.#"; 42.5
PRINT USING "$$##.##"; 9.5
PRINT USING "**$###.##"; 12.75
PRINT USING "#,###,###"; 1234567
PRINT USING "##.##^^^^"; 1234.5
PRINT USING "##"; 123
PRINT USING "!"; "pointcalc"
PRINT USING "\   \"; "QBasic"
PRINT USING "Name: & age ##"; "Ann"; 31; "Bob"; 7
PRINT USING "_#_# ##"; 5
PRINT USING "##.## "; 1; 2; 3;
PRINT "|"
' a price list: item, quantity, price, total
DATA "Compass", 2, 3.25, "Protractor", 10, .8, "Drawing board", 1, 24.5
f$ = "\          \ ### $$##.## $$###.##"
total = 0
FOR i = 1 TO 3
  READ item$, n, price
  PRINT USING f$; item$; n; price; n * price
  total = total + n * price
NEXT i
PRINT USING "Total:                     **$##.##"; total
