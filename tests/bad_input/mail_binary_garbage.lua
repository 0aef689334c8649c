-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_binary_garbage\.lua:5: .*mail_binary_garbage\.mail:1: binary byte 0x7f at column 1: this is not an ASTER text mesh \(\.mail\)
-- Binary bytes where an ASTER mesh is expected.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
