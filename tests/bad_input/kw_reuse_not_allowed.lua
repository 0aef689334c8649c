-- expect-exit: 2
-- expect-output: <F> <DEFI_FONCTION> .*kw_reuse_not_allowed\.lua:6: DEFI_FONCTION does not accept reuse=
-- reuse= on a command that does not allow it.
DEBUT{}
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
F = DEFI_FONCTION{reuse = F, NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 2.0}}
FIN{}
