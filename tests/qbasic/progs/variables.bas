' undeclared variables are 0 (strings ""), names are case-insensitive, scalars and arrays of
' one name are distinct, the type suffixes make distinct variables, stores round to the type
PRINT x; LEN(a$); "|"; a$; "|"
Abc = 5: PRINT aBC; ABC
a = 1: a(1) = 2: PRINT a; a(1)
x = 1: x# = 2: x% = 3: x$ = "s": x& = 70000: PRINT x; x#; x%; x$; x&
i% = 2.5: j% = 3.5: k% = -2.5: m& = 1.5: PRINT i%; j%; k%; m&
s = 1 / 3: d# = 1 / 3: e# = 1# / 3: PRINT s; d#; e#
y = .1: PRINT y = .1; y; y * 3
big = 16777217: PRINT big; big = 16777216
DIM q(1 TO 3, 2): q(3, 2) = 7: PRINT q(3, 2); q(2.6, 1.5); LBOUND(q); UBOUND(q); UBOUND(q, 2)
b(10) = 4: PRINT b(10); b(0)
k = 2: DIM c$(k): c$(2) = "two": PRINT c$(2); c$(0); "|"
DEFINT I-J: i = 2.6: PRINT i; i / 2
SWAP x, y: PRINT x; y
' SINGLE arithmetic never wraps around like integers: 100000^4 = 1E+20
a = 100000: PRINT a * a * a * a; 12345678; STR$(12345678); STR$(1.5E+10)
