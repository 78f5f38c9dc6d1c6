' video memory at &HA000 with POKE/PEEK, the BIOS keyboard flags, the DAC ports
SCREEN 13
DEF SEG = &HA000
FOR x = 0 TO 319
  POKE 100 * 320& + x, x MOD 256
NEXT
PRINT PEEK(100 * 320& + 40)
DEF SEG = 0
flags = PEEK(&H417)
DEF SEG
PRINT flags
OUT &H3C8, 1: OUT &H3C9, 63: OUT &H3C9, 63: OUT &H3C9, 0
LINE (0, 150)-(50, 160), 1, BF
