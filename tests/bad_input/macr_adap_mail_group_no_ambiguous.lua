-- expect-exit: 2
-- expect-output: <F> <MACR_ADAP_MAIL> .*macr_adap_mail_group_no_ambiguous\.lua:8: GROUP_NO 'ENCASTRE': the new node N[0-9]+ lies between its nodes N[145], N[145] and no group of cells has exactly its nodes\. Which new nodes belong to such a group of nodes cannot be told: define it from cells
-- A group of nodes that refinement cannot follow: new nodes lie between its
-- nodes, and no group of cells has exactly its nodes to tell which belong to
-- it. Before, the refined mesh kept the group's old nodes only, and a
-- DDL_IMPO on it silently left the new nodes of that boundary free.
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA, MAILLAGE_NP1 = CO('MA1')}
MO = AFFE_MODELE{MAILLAGE = MA1, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_NO = 'ENCASTRE', DX = 0.0, DY = 0.0}}
FIN{}
