' EXPECT: 3: SHELL: not supported by pointcalc
SCREEN 12
SHELL "dir"
