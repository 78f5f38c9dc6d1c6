' precedence: ^ > unary - > * / > \ > MOD > + - > relational > NOT > AND > OR > XOR
PRINT 2 + 3 * 4; (2 + 3) * 4; -2 ^ 2; 2 ^ 3 ^ 2; 2 ^ -1
PRINT 7 \ 2; -7 \ 2; 7 MOD 3; -7 MOD 3; 7.6 \ 2; 10 MOD 3.4
PRINT 7 \ 2 MOD 2; 10 - 7 MOD 4; 2 * 3 MOD 4; 8 / 2 / 2; 12 \ 2 * 3: ' 12 \ (2 * 3)
PRINT 3 > 2; 3 < 2; 3 = 3; 1 <> 1; 2 >= 2; 1 <= 0
PRINT 5 AND 3; 5 OR 3; 5 XOR 3; NOT 5; NOT 0; 6 EQV 3; 6 IMP 3
PRINT 1 + 2 = 3 AND 4 > 5; NOT 1 = 2; (1 < 2) + (2 < 3)
PRINT -(-3); 2 * -3; -2 * -3; (-2) ^ 2; (-8) ^ (1 / 1)
a = 3: b = 4: PRINT SQR(a * a + b * b); ABS(-2.5); INT(-2.5); FIX(-2.5); SGN(-7); CINT(2.5); CINT(3.5)
PRINT "ab" + "cd"; "a" < "b"; "abc" = "abc"
' INTEGER and LONG products up to the type's limits (beyond: Overflow, errors/overflow_product.bas)
PRINT 181 * 181; -128 * 256; 46340& * 46340; 65536 * -32768; 3 * 2.5
