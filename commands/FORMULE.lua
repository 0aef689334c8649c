return OPER{ nom = 'FORMULE', sd_prod = 'formule', reentrant = 'n',
  fr = "Defines a formula of named parameters: an expression text or a Lua function.",
  SIMP{ 'VALE', statut = 'o', typ = {'TXM', 'lua_function'},
        fr = "The expression ('X**2 + sin(Y)', Python syntax with **) or a Lua function of the parameters." },
  SIMP{ 'NOM_PARA', statut = 'o', typ = 'TXM', max = '**',
        fr = "Parameter names, in the order the Lua function takes them (X, Y, INST, ...)." },
}
