' EXPECT: 3: Illegal function call
' COLOR with a border colour is text mode's only
SCREEN 12: COLOR 14, 1, 4
