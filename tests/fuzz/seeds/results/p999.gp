set terminal pngcairo size 1100,460 font ',9' noenhanced
set output 'p999.png'
set logscale y
set yrange [0.01:*]
set ylabel 'p99.9 error (1/65535)'
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set key outside top center horizontal
set xtics rotate by -45 scale 0
set grid ytics
set xtics ('tiny' 0)
plot 'p999.dat' using 2 title 'reference-standin'
