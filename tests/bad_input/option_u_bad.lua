-- expect-exit: 2
-- expect-output: <F> <aster-lite> -u expects N=PATH with a positive unit number N, got 'twenty=.*base\.mail'
-- args: -u twenty=@DIR@/base.mail --output-dir @OUT@
-- -u with a bad argument.
DEBUT{}
FIN{}
