-- expect-exit: 2
-- expect-output: <F> <LUA> .*table_growth\.lua:6: not enough memory \(the study asks for more than the system gives it\)
-- Run under prlimit --as: a table that grows until the address space is full.
local t = {}
for i = 1, 1e10 do
  t[i] = string.rep('x', 1e6) .. i
end
