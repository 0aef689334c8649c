-- expect-exit: 2
-- expect-output: <F> <aster-lite> unknown option --frobnicate
-- args: --frobnicate --output-dir @OUT@
-- An unknown command-line option.
DEBUT{}
FIN{}
