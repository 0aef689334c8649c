# The plot of docs/verification/viscoplasticity.md: the errors the time-step tests measure
# (Lemaitre.NortonRelaxationConvergesAtTheOrderOfTheScheme,
# ViscEndoLemaitre.ImplicitEulerIsFirstOrderInTheStep), against the number of steps.
#   gnuplot docs/verification/time_step_convergence.gp
set terminal pngcairo size 800,520 font ",11" noenhanced
set output 'docs/verification/time_step_convergence.png'
set title "Error against the closed form over a fixed time, by the number of steps"
set logscale xy
set grid
set format y "%g"
set xlabel "steps"
set ylabel "relative error"
set key right top
$norton1 << END
10 3.86e-2
20 1.99e-2
40 1.01e-2
END
$norton05 << END
10 1.16e-3
20 2.90e-4
40 7.26e-5
END
$endo << END
100 4.30e-3
200 2.12e-3
400 1.05e-3
END
plot $norton1 using 1:2 with linespoints title "NORTON relaxation, PARM_THETA = 1 (order 1)", \
     $norton05 using 1:2 with linespoints title "NORTON relaxation, PARM_THETA = 0.5 (order 2)", \
     $endo using 1:2 with linespoints title "VISC_ENDO_LEMA damage at 0.8 t_c, implicit Euler (order 1)", \
     0.386 / x with lines dashtype 2 lc rgb "gray" title "slope -1", \
     0.116 / x**2 with lines dashtype 3 lc rgb "gray" title "slope -2"
