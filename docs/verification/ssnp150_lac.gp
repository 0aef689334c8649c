# Pressure L2 error of SSNP150 with LAC (studies/ssnp150c-f.lua, structured meshes),
# both LAGS_C spaces, against h = 1/N. Data: the studies' output (2026-11-25).
set terminal pngcairo size 1000,420 font ',10'
set output 'ssnp150_lac_pressure.png'
set multiplot layout 1,2
set logscale xy
set format y '10^{%L}'
set xlabel "h"
set ylabel "||p - p_{ex}||_{L2(BAS)}"
set key bottom right
set grid
$TRIA3_NOEUD << EOD
0.5 7.084421e-03
0.25 2.175525e-03
0.125 6.440543e-04
0.0625 2.692657e-04
0.03125 1.073515e-04
0.015625 4.047794e-05
EOD
$QUAD4_NOEUD << EOD
0.5 7.144517e-03
0.25 1.974249e-03
0.125 5.721778e-04
0.0625 1.685671e-04
0.03125 5.072268e-05
0.015625 1.574804e-05
EOD
$TRIA6_NOEUD << EOD
0.5 1.300870e-03
0.25 5.232564e-04
0.125 1.485818e-04
0.0625 3.882109e-05
0.03125 9.876864e-06
0.015625 2.488182e-06
EOD
$QUAD8_NOEUD << EOD
0.5 5.103152e-04
0.25 5.577129e-05
0.125 7.599519e-06
0.0625 1.249808e-06
0.03125 2.185666e-07
0.015625 3.871051e-08
EOD
$TRIA3_PAIRE << EOD
0.5 7.645681e-03
0.25 2.171517e-03
0.125 5.896576e-04
0.0625 1.960610e-04
0.03125 7.431067e-05
0.015625 2.798380e-05
EOD
$QUAD4_PAIRE << EOD
0.5 5.870009e-03
0.25 1.938837e-03
0.125 5.347344e-04
0.0625 1.521949e-04
0.03125 4.428674e-05
0.015625 1.321655e-05
EOD
$TRIA6_PAIRE << EOD
0.5 5.050121e-04
0.25 4.304493e-05
0.125 1.379286e-05
0.0625 3.229867e-06
0.03125 7.107384e-07
0.015625 1.585287e-07
EOD
$QUAD8_PAIRE << EOD
0.5 4.985085e-04
0.25 5.536849e-05
0.125 6.923764e-06
0.0625 1.012182e-06
0.03125 1.582142e-07
0.015625 2.590343e-08
EOD
set title "ESPACE\\_LAGS\\_C = 'NOEUD' (structured meshes)"
plot $TRIA3_NOEUD using 1:2 with linespoints title 'TRIA3', \
     $QUAD4_NOEUD using 1:2 with linespoints title 'QUAD4', \
     $TRIA6_NOEUD using 1:2 with linespoints title 'TRIA6', \
     $QUAD8_NOEUD using 1:2 with linespoints title 'QUAD8', \
     0.02*x**1.5 with lines dt 2 lc 'gray' title 'h^{1.5}', \
     0.01*x**2.5 with lines dt 3 lc 'gray' title 'h^{2.5}'
set title "ESPACE\\_LAGS\\_C = 'PAIRE' (structured meshes)"
plot $TRIA3_PAIRE using 1:2 with linespoints title 'TRIA3', \
     $QUAD4_PAIRE using 1:2 with linespoints title 'QUAD4', \
     $TRIA6_PAIRE using 1:2 with linespoints title 'TRIA6', \
     $QUAD8_PAIRE using 1:2 with linespoints title 'QUAD8', \
     0.02*x**1.5 with lines dt 2 lc 'gray' title 'h^{1.5}', \
     0.01*x**2.5 with lines dt 3 lc 'gray' title 'h^{2.5}'
unset multiplot
