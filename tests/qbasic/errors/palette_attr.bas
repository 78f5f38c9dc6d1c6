' EXPECT: 3: Illegal function call
' PALETTE's attribute must be one of the mode's
SCREEN 12: PALETTE 16, 63
