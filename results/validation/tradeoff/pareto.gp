set terminal pngcairo size 1000,700 font ',9' noenhanced
set output 'pareto.png'
set lmargin at screen 0.09
set rmargin at screen 0.97
set bmargin at screen 0.09
set tmargin at screen 0.93
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set xrange [0.0100037:7.93311]
set yrange [20.1684:10918.2]
set xlabel 'frame time, median (s)'
set ylabel 'RMSE (1/65535) against the converged reference'
set title 'table2_knot_yiq 720x720: error against frame time (Pareto-optimal in red)'
set key top right box opaque
set arrow from graph 0, first 32.2694 to graph 1, first 32.2694 nohead dt 2 lc rgb '#3060c0'
set label "converged reference's residual (errors closer than this are not resolved)" at graph 0.01, first 36.1417 tc rgb '#3060c0'
set label "corner:fast" at graph 0.0806308, graph 0.764515 left font ',9:Bold' tc rgb '#c02020' front
set label "precision=float" at graph 0.113752, graph 0.670958 left font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-4spp" at graph 0.140092, graph 0.52404 left font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-16spp" at graph 0.322138, graph 0.472788 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:accurate" at graph 0.602037, graph 0.30175 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:fast-gouraud" at graph 0.0807389, graph 0.925326 left font ',8' tc rgb '#606060' front
set label "tess=0.25" at graph 0.211441, graph 0.873117 right font ',8' tc rgb '#606060' front
set label "shading=gouraud" at graph 0.244982, graph 0.855042 left font ',8' tc rgb '#606060' front
set label "tess=0.5" at graph 0.231827, graph 0.770829 left font ',8' tc rgb '#606060' front
set label "shading=flat" at graph 0.255098, graph 0.74969 left font ',8' tc rgb '#606060' front
set label "filter=nearest" at graph 0.231607, graph 0.733309 right font ',8' tc rgb '#606060' front
set label "base" at graph 0.269935, graph 0.694768 left font ',8' tc rgb '#606060' front
set label "tess=2" at graph 0.31396, graph 0.685194 left font ',8' tc rgb '#606060' front
set label "spp=4" at graph 0.426934, graph 0.54785 left font ',8' tc rgb '#606060' front
set label "spp=16" at graph 0.604959, graph 0.496598 left font ',8' tc rgb '#606060' front
set label "spp=64" at graph 0.802569, graph 0.490389 left font ',8' tc rgb '#606060' front
plot 'pareto.dat' index 0 using 2:3 with points pt 7 ps 1.1 lc rgb '#909090' title 'configuration', \
     '' index 1 using 2:3 with linespoints pt 7 ps 1.4 lw 1.5 lc rgb '#c02020' title 'Pareto-optimal'
