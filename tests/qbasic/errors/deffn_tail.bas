' EXPECT: 3: Out of stack space
' a DEF FN calling itself in its own tail: no Lua tail call, QBasic's stack overflow
DEF FNa (x) = FNa(x + 1)
PRINT FNa(1)
