-- expect-exit: 2
-- expect-output: <F> <LUA> .*lua_undefined_command\.lua:5: 'DEFI_MATERIAUX' is not defined. did you mean DEFI_MATERIAU or AFFE_MATERIAU\?
-- A misspelt command.
DEBUT{}
MAT = DEFI_MATERIAUX{ELAS = {E = 1000.0, NU = 0.3}}
FIN{}
