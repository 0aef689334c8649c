-- expect-exit: 2
-- expect-output: <F> <LUA> .*string_too_large\.lua:5: resulting string too large
-- Run under prlimit --as (tests/program/CMakeLists.txt): a string of 10 GB is
-- refused by Lua at once, with the line.
local s = string.rep('x', 1e10)
print(#s)
