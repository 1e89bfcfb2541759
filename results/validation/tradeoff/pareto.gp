set terminal pngcairo size 1000,700 font ',9' noenhanced
set output 'pareto.png'
set lmargin at screen 0.09
set rmargin at screen 0.97
set bmargin at screen 0.09
set tmargin at screen 0.93
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set xrange [0.00301839:7.42065]
set yrange [20.1697:10918.2]
set xlabel 'frame time, median (s)'
set ylabel 'RMSE (1/65535) against the converged reference'
set title 'table2_knot_yiq 720x720: error against frame time (Pareto-optimal in red)'
set key top right box opaque
set arrow from graph 0, first 32.2716 to graph 1, first 32.2716 nohead dt 2 lc rgb '#3060c0'
set label "converged reference's residual (errors closer than this are not resolved)" at graph 0.01, first 36.1442 tc rgb '#3060c0'
set label "corner:fast-gouraud" at graph 0.0704278, graph 0.901516 left font ',9:Bold' tc rgb '#c02020' front
set label "corner:fast" at graph 0.10189, graph 0.764512 right font ',9:Bold' tc rgb '#c02020' front
set label "precision=float" at graph 0.151765, graph 0.670955 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-4spp" at graph 0.311119, graph 0.524035 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:float-16spp" at graph 0.473292, graph 0.472782 right font ',9:Bold' tc rgb '#c02020' front
set label "corner:accurate" at graph 0.656298, graph 0.301737 right font ',9:Bold' tc rgb '#c02020' front
set label "tess=0.25" at graph 0.336295, graph 0.873116 left font ',8' tc rgb '#606060' front
set label "shading=gouraud" at graph 0.31185, graph 0.855041 right font ',8' tc rgb '#606060' front
set label "tess=0.5" at graph 0.352143, graph 0.770826 left font ',8' tc rgb '#606060' front
set label "shading=flat" at graph 0.338961, graph 0.749687 right font ',8' tc rgb '#606060' front
set label "filter=nearest" at graph 0.365397, graph 0.733306 left font ',8' tc rgb '#606060' front
set label "base" at graph 0.347042, graph 0.694765 right font ',8' tc rgb '#606060' front
set label "tess=2" at graph 0.403392, graph 0.68519 left font ',8' tc rgb '#606060' front
set label "spp=4" at graph 0.51016, graph 0.547844 left font ',8' tc rgb '#606060' front
set label "spp=16" at graph 0.672996, graph 0.496591 left font ',8' tc rgb '#606060' front
set label "spp=64" at graph 0.832663, graph 0.490383 left font ',8' tc rgb '#606060' front
plot 'pareto.dat' index 0 using 2:3 with points pt 7 ps 1.1 lc rgb '#909090' title 'configuration', \
     '' index 1 using 2:3 with linespoints pt 7 ps 1.4 lw 1.5 lc rgb '#c02020' title 'Pareto-optimal'
