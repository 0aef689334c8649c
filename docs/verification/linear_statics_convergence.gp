# Draws linear_statics_convergence.png (docs/verification/linear_statics.md):
#   gnuplot linear_statics_convergence.gp
# The errors are those the tests print (ctest -R 'Lame|kirsch' -V).
set terminal pngcairo size 1000,430 font ',10' noenhanced
set output 'linear_statics_convergence.png'
set multiplot layout 1,2
set logscale xy
set format y '%.0e'
set xlabel 'h (relative)'
set key bottom right
set grid
set title "Lamé's thick cylinder: L2 error of the displacement"
$lame << EOD
1      5.038e-05  2.361e-06  8.503e-04  1.134e-05
0.5    1.304e-05  3.067e-07  2.251e-04  1.392e-06
0.25   3.29e-06   3.873e-08  5.707e-05  1.73e-07
EOD
plot $lame u 1:2 w lp pt 7 t 'AXIS, QUAD4', \
     $lame u 1:3 w lp pt 7 t 'AXIS, QUAD8', \
     $lame u 1:4 w lp pt 5 t 'D_PLAN, TRIA3', \
     $lame u 1:5 w lp pt 5 t 'D_PLAN, TRIA6', \
     5e-5*x**2 w l dt 2 lc 'black' t 'h**2', 2.4e-6*x**3 w l dt 3 lc 'black' t 'h**3'
set title "Kirsch's plate: SIGM_NOEU SIXX at the top of the hole"
set ylabel 'relative error'
$kirsch << EOD
1     6.757e-03
0.5   2.228e-03
0.25  6.487e-04
EOD
plot $kirsch u 1:2 w lp pt 7 t 'C_PLAN, QUAD8', 6.757e-3*x**2 w l dt 2 lc 'black' t 'h**2'
unset multiplot
