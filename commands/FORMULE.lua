return OPER{ nom = 'FORMULE', sd_prod = 'formule', reentrant = 'n',
  fr = "Defines a formula of named parameters: an expression text or a Lua function.",
  SIMP{ 'VALE', statut = 'o', typ = {'TXM', 'lua_function'},
        fr = "The expression ('X**2 + sin(Y)', Python syntax with **) or a Lua function of the parameters." },
  SIMP{ 'NOM_PARA', statut = 'o', typ = 'TXM', max = '**',
        fr = "Parameter names, in the order the Lua function takes them (X, Y, INST, ...)." },
  -- code_aster's idiom FORMULE(VALE='A*X', A=A, NOM_PARA='X'): the other keywords
  -- are Python values the expression sees by name.
  autres_mots_cles = SIMP{ 'CONTEXTE', typ = {'R', 'fonction_sdaster', 'formule'},
        fr = "A name the expression text uses (A = 2.5, F = a function): a real, "
          .. "substituted as a constant, or a function called as F(...) with as many arguments as it has parameters." },
}
