' INPUT with prompts and several values, LINE INPUT, WIDTH
INPUT "Your name"; n$
INPUT "Age, height"; age, h
LINE INPUT "Comment: "; c$
PRINT "Hi "; n$; age; h; "["; c$; "]"
WIDTH 40
PRINT "wide"
