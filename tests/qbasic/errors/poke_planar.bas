' EXPECT: 4: video memory &HA000:&H0 outside SCREEN 13: not supported by pointcalc
' SCREEN 12's planar video memory is not emulated
SCREEN 12: DEF SEG = &HA000
POKE 0, 255
