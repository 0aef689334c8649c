-- expect-exit: 2
-- expect-output: <F> <LUA> .*string_growth\.lua:6: not enough memory \(the study asks for more than the system gives it\)
-- Run under prlimit --as: a string of 1.2 GB does not fit in 1 GB of address
-- space; the message names the line (Lua's own says "not enough memory" alone).
local s = string.rep('x', 3e8)
local t = s .. s .. s .. s
print(#s, #t)
