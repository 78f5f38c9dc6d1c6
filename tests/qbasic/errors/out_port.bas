' EXPECT: 3: OUT to port &H61: not supported by pointcalc (the VGA DAC ports &H3C7, &H3C8, &H3C9 are)
' the PC speaker's port: real hardware pointcalc does not emulate
OUT &H61, INP(&H3C8) OR 3
