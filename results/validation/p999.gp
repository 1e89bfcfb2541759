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
set xtics ('control_knot_magnified_texture' 0, 'control_knot_untextured' 1, 'fig1_phong_behind' 2, 'fig1_phong_front' 3, 'fig1_phong_specular' 4, 'fig1_yiq_behind' 5, 'fig1_yiq_front' 6, 'fig1_yiq_specular' 7, 'former_complex_attenuation_several' 8, 'former_course_textured_highlight' 9, 'former_linear_attenuation_several' 10, 'former_yiq_saturated_attenuated' 11, 'forsyth_bidirectional' 12, 'forsyth_hemispherical' 13, 'forsyth_lambert' 14, 'forsyth_trilight' 15, 'forsyth_wrap_around' 16, 'light_ambient_only' 17, 'light_directional' 18, 'light_point_attenuation' 19, 'light_spot' 20, 'lights_several' 21, 'mesh_boxtextured_glb' 22, 'mesh_boxtextured_gltf' 23, 'mesh_objects_textured' 24, 'mesh_objects_transformed_untextured' 25, 'mesh_spider_obj' 26, 'mesh_spider_obj_untextured' 27, 'mesh_suzanne_gltf_untextured' 28, 'mesh_suzanne_obj_untextured' 29, 'mesh_wuson_obj' 30, 'mesh_wuson_ply' 31, 'mesh_wuson_stl' 32, 'object_materials' 33, 'shading_flat' 34, 'shading_gouraud' 35, 'shading_phong' 36, 'table2_knot_phong' 37, 'table2_knot_yiq' 38, 'texture16_bilinear_37x23' 39, 'texture16_nearest_37x23' 40)
plot 'p999.dat' using 2 title 'reference-povray', '' using 3 title 'reference-blender', '' using 4 title 'reference-eevee', '' using 5 title 'reference-gl', '' using 6 title 'povray-blender', '' using 7 title 'povray-eevee', '' using 8 title 'povray-gl', '' using 9 title 'blender-eevee', '' using 10 title 'blender-gl', '' using 11 title 'eevee-gl'
