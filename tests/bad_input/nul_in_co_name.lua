-- expect-exit: 2
-- expect-output: <F> <CO> .*nul_in_co_name\.lua:5: the name 'RES\\0U' contains a NUL byte \('\\0'\)
-- A NUL byte in the name of a concept to create.
DEBUT{}
local name = CO('RES\0U')
