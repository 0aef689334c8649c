-- The fields stored in a result (evol_noli, evol_elas), for NOM_CHAM: those the
-- analyses store and those CALC_CHAMP adds.
function C_NOM_CHAM_INTO()
  return {'DEPL', 'SIEF_ELGA', 'SIEF_ELNO', 'SIEF_NOEU', 'SIGM_ELGA', 'SIGM_ELNO', 'SIGM_NOEU',
          'EPSI_ELGA', 'EPSI_ELNO', 'EPSI_NOEU', 'EPSG_ELGA', 'EPSG_ELNO', 'EPSG_NOEU',
          'EPSP_ELGA', 'EPSP_ELNO', 'EPSP_NOEU',
          'SIEQ_ELGA', 'SIEQ_ELNO', 'SIEQ_NOEU', 'VARI_ELGA', 'VARI_ELNO', 'VARI_NOEU',
          'FORC_NODA', 'REAC_NODA', 'CONT_NOEU', 'CONT_ELEM'}
end
