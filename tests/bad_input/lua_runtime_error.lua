-- expect-exit: 2
-- expect-output: <F> <LUA> .*lua_runtime_error\.lua:7: attempt to perform arithmetic on a nil value
-- A Lua runtime error in the middle of a study.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
local n = #MA:getCells('SURFACE') + nil
FIN{}
