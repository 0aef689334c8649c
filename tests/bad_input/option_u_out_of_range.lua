-- expect-exit: 2
-- expect-output: <F> <aster-lite> -u expects N=PATH with a unit number N from 1 to 2147483647, got '4294967316=.*base\.mail'
-- args: -u 4294967316=@DIR@/base.mail --output-dir @OUT@
-- A unit number beyond a C++ int (it bound unit 20, 4294967316 modulo 2^32).
DEBUT{}
FIN{}
