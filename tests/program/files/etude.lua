-- Reads its mesh from etude.med beside it (unit 20's default), and writes it
-- back with IMPR_RESU{FORMAT='MED'} twice without a unit, a table and the
-- listing: run by outputs_test.sh with --output-dir set to the study's folder.
MAIL = LIRE_MAILLAGE{FORMAT = 'MED'}
IMPR_RESU{FORMAT = 'MED', RESU = {MAILLAGE = MAIL}}
IMPR_RESU{FORMAT = 'MED', RESU = {MAILLAGE = MAIL}}
T = CREA_TABLE{LISTE = {{PARA = 'N', LISTE_I = {1, 2, 3}}}}
IMPR_TABLE{TABLE = T}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {MAILLAGE = MAIL}}
FIN{}
