10 REM A GW-BASIC listing as it was saved from the prompt: the commands typed there (LIST,
20 REM SAVE, RUN) sit between and after the numbered lines; they are not part of the program.
30 FOR I = 1 TO 3
40 PRINT "line"; I * 10
50 NEXT I
LIST 10-50
60 PRINT "end of the listing"
SAVE "GWDEMO.BAS",A
RUN
