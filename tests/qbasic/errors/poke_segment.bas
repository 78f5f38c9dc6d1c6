' EXPECT: 4: POKE at &HB800:&H0: not supported by pointcalc (emulated: &HA000 in SCREEN 13, 0:&H417)
' text-mode video memory is not emulated (PRINT is the text screen)
DEF SEG = &HB800
POKE 0, 65
