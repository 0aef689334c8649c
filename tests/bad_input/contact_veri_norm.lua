-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_veri_norm\.lua:8: ZONE\[1\]/GROUP_MA_ESCL: the normal of cell M13 \(group .BAS_INV.\) points into the cell M1 it bounds; contact normals must point outwards: orient the group with MODI_MAILLAGE/ORIE_PEAU, or give VERI_NORM=.NON.
-- VERI_NORM='OUI' (the default): a slave walked the wrong way round stops DEFI_CONTACT.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS_INV'}}
