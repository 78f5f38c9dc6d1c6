' A program that expects a person, run from a file of answers (keyboard.in): INPUT with a
' prompt and several fields (a bad line is "Redo from start"), LINE INPUT, INKEY$ and INPUT$
' taking keys, RANDOMIZE asking for its seed, the virtual clock of TIMER, SLEEP and SOUND,
' sounds accepted silently, and a "press any key" loop that ends when the input has run out.
KEY OFF
INPUT "Name and age"; n$, age
PRINT "Hello, "; n$; ", next year you are"; age + 1
LINE INPUT "Motto: "; m$
PRINT "["; m$; "]"
k$ = INKEY$: PRINT "key "; k$; ASC(INKEY$)
PRINT "three keys: "; INPUT$(3); " and Enter:"; ASC(INPUT$(1))
RANDOMIZE
PRINT RND
t0 = TIMER
DO: LOOP WHILE TIMER < t0 + 1
PRINT "a one-second delay loop took"; TIMER - t0; "virtual seconds"
t0 = TIMER: SLEEP 2: PRINT "SLEEP 2:"; TIMER - t0 > 2
BEEP: SOUND 440, 18.2: PLAY "T120 L4 C D E"
PRINT "Press any key"
polls = 0
DO: polls = polls + 1: LOOP WHILE INKEY$ = ""
PRINT "answered after"; polls; "polls"
INPUT "Last question"; q
PRINT "not reached: INPUT with no input left ends the program"
