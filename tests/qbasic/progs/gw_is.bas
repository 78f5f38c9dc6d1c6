10 REM GW-BASIC has no SELECT CASE: IS is an ordinary variable name there
20 IS = 3: IS$ = "three"
30 FOR I = 1 TO IS: PRINT I;: NEXT: PRINT IS$
