-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*nul_in_keyword_name\.lua:5: keyword name 'E\\0X' in ELAS contains a NUL byte \('\\0'\)
-- A NUL byte in a keyword name (it was read as E).
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {['E\0X'] = 1.0, NU = 0.3}}
