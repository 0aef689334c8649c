-- expect-exit: 2
-- expect-output: <F> <PRE_GMSH> .*pre_gmsh_unknown_type\.lua:5: .*pre_gmsh_unknown_type\.msh:10: element 2 has gmsh type 21, which PRE_GMSH does not convert \(expected 1 to 19
-- A gmsh MSH 1 file with a 10-node triangle (type 21), which code_aster's PRE_GMSH does not convert.
DEBUT{}
PRE_GMSH{}
FIN{}
