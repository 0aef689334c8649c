-- expect-exit: 2
-- expect-output: <F> <LUA> .*sandbox_write_outside\.lua:7: io\.open cannot write '\.\./sandbox_write_outside\.txt': a sandboxed study writes files only below its output folder .*sandbox_write_outside \(a relative path is taken from there\) \(aster-lite --unsafe-lua lifts the sandbox\)
-- A sandboxed study writes files below its output folder only (relative
-- paths are taken there): ../ is outside.
local f = assert(io.open('inside.txt', 'w'))
f:close()
io.open('../sandbox_write_outside.txt', 'w')
FIN{}
