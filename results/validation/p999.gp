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
set xtics ('control_knot_magnified_texture' 0, 'control_knot_untextured' 1, 'fig1_phong_behind' 2, 'fig1_phong_front' 3, 'fig1_phong_specular' 4, 'fig1_yiq_behind' 5, 'fig1_yiq_front' 6, 'fig1_yiq_specular' 7, 'forsyth_bidirectional' 8, 'forsyth_hemispherical' 9, 'forsyth_lambert' 10, 'forsyth_trilight' 11, 'forsyth_wrap_around' 12, 'light_ambient_only' 13, 'light_directional' 14, 'light_point_attenuation' 15, 'light_spot' 16, 'lights_several' 17, 'shading_flat' 18, 'shading_gouraud' 19, 'shading_phong' 20, 'table2_knot_phong' 21, 'table2_knot_yiq' 22, 'texture16_bilinear_37x23' 23, 'texture16_nearest_37x23' 24)
plot 'p999.dat' using 2 title 'reference-povray', '' using 3 title 'reference-blender', '' using 4 title 'povray-blender'
