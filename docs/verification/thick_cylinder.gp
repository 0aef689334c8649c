# The plots of docs/verification/plasticity.md from studies/thick_cylinder_hill.lua:
#   aster-lite --output-dir /tmp/hill studies/thick_cylinder_hill.lua
#   gnuplot -e "out='/tmp/hill'" docs/verification/thick_cylinder.gp
if (!exists("out")) out = '/tmp/hill'
a = 1.0; b = 2.0; E = 210000.0; nu = 0.3; SY = 240.0
k = SY / sqrt(3.0); c = 1.5
p1 = k * (1 - c**2 / b**2 + 2 * log(c / a))
pL = 2 * k * log(b / a)
pe = k * (1 - a**2 / b**2)
ue = (1 + nu) / E * pe * a**2 / (b**2 - a**2) * ((1 - 2 * nu) * a + b**2 / a)
# Hill's stresses at p1 (plastic zone r < c, elastic beyond).
sr(r) = r < c ? -p1 + 2 * k * log(r / a) : -k * c**2 / b**2 * (b**2 / r**2 - 1)
st(r) = r < c ? sr(r) + 2 * k : k * c**2 / b**2 * (b**2 / r**2 + 1)

set terminal pngcairo size 800,520 font ",11" noenhanced
set grid
set key left top

set output 'docs/verification/thick_cylinder_stresses.png'
set title sprintf("Thick cylinder, p = %.2f (plastic radius c = 1.5): stresses along Y = 0", p1)
set xlabel 'r'
set ylabel 'stress'
set key left center
set arrow from c, graph 0 to c, graph 1 nohead dashtype 2
plot [1:2] sr(x) lw 2 lc rgb '#1f77b4' title "Hill: sigma_r", \
     st(x) lw 2 lc rgb '#d62728' title "Hill: sigma_theta", \
     out.'/PROFIL.tab' every 4 using 6:8 with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'aster-lite SIXX (SIGM_NOEU)', \
     '' every 4 using 6:9 with points pt 7 ps 0.8 lc rgb '#d62728' title 'aster-lite SIYY (SIGM_NOEU)'
unset arrow

set output 'docs/verification/thick_cylinder_pressure.png'
set title "Thick cylinder driven out at the bore: pressure against the bore's displacement"
set xlabel 'u_a / u_e (u_e: the displacement at first yield)'
set ylabel 'pressure p (reactions on the bore)'
set key right bottom
plot [0:10] [0:210] out.'/FORCE.tab' using (10 * $3):4 with linespoints pt 7 ps 0.7 lw 2 title 'aster-lite', \
     pL lw 2 dashtype 2 title sprintf('Hill: limit pressure p_L = %.2f', pL), \
     (x < 1 ? pe * x : 1/0) lw 2 lc rgb '#2ca02c' title 'elastic (Lame)', \
     pe lw 1 dashtype 3 lc rgb '#2ca02c' title sprintf('first yield p_e = %.2f', pe)
