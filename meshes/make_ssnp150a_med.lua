-- Makes ssnp150a.med, the mesh of SSNP150 version A: ssnp150.geo meshed by gmsh
-- with its default N = 16 (a 16 x 16 grid of QUAD8 on the unit square, its four
-- edges as SEG3 groups BAS, DROITE, HAUT, GAUCHE, and the rigid master MAITRE).
-- Run: aster-lite --unsafe-lua -u 20=meshes/ssnp150.geo -u 80=ssnp150a.med meshes/make_ssnp150a_med.lua
DEBUT{}

MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}

-- (N+1)^2 vertices + 2 N (N+1) mid-edge nodes + 3 nodes of MAITRE; N^2 QUAD8 + 4 N SEG3 + 1.
local N = 16
local nodes = (N + 1)^2 + 2 * N * (N + 1) + 3
local cells = N * N + 4 * N + 1
if MAIL:getNumberOfNodes() ~= nodes or MAIL:getNumberOfCells() ~= cells then
  error(string.format('ssnp150.geo gave %d nodes and %d cells; expected %d and %d (is N still 16?)',
                      MAIL:getNumberOfNodes(), MAIL:getNumberOfCells(), nodes, cells))
end

IMPR_RESU{FORMAT = 'MED', UNITE = 80, RESU = {MAILLAGE = MAIL}}

FIN{}
