-- expect-exit: 2
-- expect-output: <F> <DEBUT> .*ignored_keyword_wrong_value\.lua:5: DEBUG: keyword SDVERI = 'OUII' is not allowed; allowed values: 'OUI', 'NON'; did you mean 'OUI'\?
-- DEBUG is accepted and ignored, but its values are still checked: a
-- misspelt value is an error, as in code_aster.
DEBUT{DEBUG = {SDVERI = 'OUII'}}
FIN{}
