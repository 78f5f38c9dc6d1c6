' SCREEN 12's attributes show the DAC entries the BIOS's palette registers name: 0-5 and 7
' their own, attribute 6 (brown) entry 20, attributes 8-15 entries 56-63.
SCREEN 12
OUT &H3C7, 20: PRINT "DAC 20 (brown):"; INP(&H3C9); INP(&H3C9); INP(&H3C9)
' entry 6 is shown by no attribute of SCREEN 12: attribute 6 stays brown
OUT &H3C8, 6: OUT &H3C9, 0: OUT &H3C9, 63: OUT &H3C9, 0
LINE (0, 100)-(99, 119), 6, BF
' entry 62 is attribute 14's (yellow): now white-blue
OUT &H3C8, 62: OUT &H3C9, 32: OUT &H3C9, 32: OUT &H3C9, 63
LINE (100, 100)-(199, 119), 14, BF
' PALETTE writes the same DAC entry: reading it back gives the new mixture
PALETTE 1, 63 + 256 * 16
OUT &H3C7, 1: PRINT "DAC 1 after PALETTE:"; INP(&H3C9); INP(&H3C9); INP(&H3C9)
