-- Makes the MED meshes of one SSNP150 mesh family (studies ssnp150c to
-- ssnp150f): for each level N of SSNP150_LEVELS, the gmsh script bound to unit
-- 20 + i (one of ssnp150_structured.geo, ssnp150_unstructured.geo,
-- ssnp150_trapezoidal.geo with N and QUADS set) meshed by gmsh and written to
-- unit 80 + i. gmsh runs .geo scripts: --unsafe-lua. meshes/CMakeLists.txt runs
-- it at build time, e.g.
--   SSNP150_KIND=trapezoidal SSNP150_QUADS=1 SSNP150_LEVELS='2 4' aster-lite --unsafe-lua \
--     -u 20=trap_N2.geo -u 21=trap_N4.geo -u 80=N2.med -u 81=N4.med meshes/make_ssnp150_family_med.lua
-- where trap_N2.geo is 'N = 2; QUADS = 1; Include "ssnp150_trapezoidal.geo";'.
DEBUT{}

local kind = assert(os.getenv('SSNP150_KIND'), 'SSNP150_KIND: structured, unstructured or trapezoidal')
local quads = assert(tonumber(os.getenv('SSNP150_QUADS')), 'SSNP150_QUADS: 1 (QUAD8) or 0 (TRIA6)') == 1
local levels = {}
for n in assert(os.getenv('SSNP150_LEVELS'), 'SSNP150_LEVELS: the values of N'):gmatch('%d+') do
  levels[#levels + 1] = tonumber(n)
end

local function check(what, got, expected, N)
  if got ~= expected then
    error(string.format('%s mesh, N = %d: %s is %d, expected %d', kind, N, what, got, expected))
  end
end

for i, N in ipairs(levels) do
  local MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19 + i}
  -- Every edge of the square: N SEG3 (2N + 1 nodes); MAITRE: one SEG3.
  for _, edge in ipairs({'BAS', 'DROITE', 'HAUT', 'GAUCHE'}) do
    check('the number of cells of ' .. edge, #MAIL:getCells(edge), N, N)
    check('the number of nodes of ' .. edge, #MAIL:getNodes(edge), 2 * N + 1, N)
  end
  check('the number of cells of MAITRE', #MAIL:getCells('MAITRE'), 1, N)
  check('the number of nodes of MAITRE', #MAIL:getNodes('MAITRE'), 3, N)
  -- Only quadrangles (or only triangles): the square's F cells with a node on
  -- every vertex and edge, 4N edges on its boundary, have 1 + 3F + 4N nodes
  -- (1 + 2F + 4N), by Euler's V - E + F = 1 and 4F (3F) = 2E - 4N.
  local F = #MAIL:getCells('SURFACE')
  check('the number of nodes of SURFACE', #MAIL:getNodes('SURFACE'), 1 + (quads and 3 or 2) * F + 4 * N, N)
  if kind ~= 'unstructured' then  -- N x N cells, each split in two triangles for TRIA6
    check('the number of cells of SURFACE', F, quads and N * N or 2 * N * N, N)
  end
  IMPR_RESU{FORMAT = 'MED', UNITE = 79 + i, RESU = {MAILLAGE = MAIL}}
  DETRUIRE{CONCEPT = {NOM = MAIL}}
end

FIN{}
