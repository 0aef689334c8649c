-- The fields stored in a result (evol_noli), for NOM_CHAM.
function C_NOM_CHAM_INTO()
  return {'DEPL', 'SIEF_ELGA', 'SIEF_NOEU', 'SIGM_NOEU', 'EPSI_ELGA', 'EPSI_NOEU',
          'VARI_ELGA', 'FORC_NODA', 'REAC_NODA', 'CONT_NOEU', 'CONT_ELEM'}
end
