set terminal pngcairo size 1000,700 font ',9' noenhanced
set output 'pareto.png'
set lmargin at screen 0.09
set rmargin at screen 0.97
set bmargin at screen 0.09
set tmargin at screen 0.93
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set xrange [0.00507126:8.98191]
set yrange [20.1697:10918.2]
set xlabel 'frame time, median (s)'
set ylabel 'RMSE (1/65535) against the converged reference'
set title 'table2_knot_yiq 720x720: error against frame time (Pareto-optimal in red)'
set key top right box opaque
set arrow from graph 0, first 32.2716 to graph 1, first 32.2716 nohead dt 2 lc rgb '#3060c0'
set label "converged reference's residual (errors closer than this are not resolved)" at graph 0.01, first 36.1442 tc rgb '#3060c0'
set label "corner:fast-gouraud" at graph 0.0730672, graph 0.901516 left font ',9:Bold' tc rgb '#c02020' front
set label "corner:fast" at graph 0.154713, graph 0.764512 right font ',9:Bold' tc rgb '#c02020' front
set label "precision=float" at graph 0.181389, graph 0.670955 right font ',9:Bold' tc rgb '#c02020' front
set label "tess=2" at graph 0.323827, graph 0.661381 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-4spp" at graph 0.361028, graph 0.524035 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-16spp" at graph 0.539793, graph 0.472782 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:accurate" at graph 0.654028, graph 0.301737 right font ',9:Bold' tc rgb '#c02020' front
set label "tess=0.25" at graph 0.282022, graph 0.873116 left font ',8' tc rgb '#606060' front
set label "shading=gouraud" at graph 0.254861, graph 0.855041 right font ',8' tc rgb '#606060' front
set label "tess=0.5" at graph 0.292738, graph 0.770826 left font ',8' tc rgb '#606060' front
set label "shading=flat" at graph 0.309973, graph 0.749687 left font ',8' tc rgb '#606060' front
set label "filter=nearest" at graph 0.292167, graph 0.733306 right font ',8' tc rgb '#606060' front
set label "base" at graph 0.283118, graph 0.694765 right font ',8' tc rgb '#606060' front
set label "spp=4" at graph 0.474811, graph 0.547844 left font ',8' tc rgb '#606060' front
set label "spp=16" at graph 0.647825, graph 0.496591 left font ',8' tc rgb '#606060' front
set label "spp=64" at graph 0.824878, graph 0.490383 left font ',8' tc rgb '#606060' front
plot 'pareto.dat' index 0 using 2:3 with points pt 7 ps 1.1 lc rgb '#909090' title 'configuration', \
     '' index 1 using 2:3 with linespoints pt 7 ps 1.4 lw 1.5 lc rgb '#c02020' title 'Pareto-optimal'
