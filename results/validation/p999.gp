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
set xtics ('blinn_phong_knot' 0, 'blinn_phong_suzanne' 1, 'control_knot_magnified_texture' 2, 'control_knot_untextured' 3, 'cook_torrance_knot_beckmann_paper' 4, 'cook_torrance_knot_ggx' 5, 'cook_torrance_suzanne_beckmann' 6, 'cook_torrance_suzanne_ggx' 7, 'fig1_phong_behind' 8, 'fig1_phong_front' 9, 'fig1_phong_specular' 10, 'fig1_yiq_behind' 11, 'fig1_yiq_behind_listing' 12, 'fig1_yiq_front' 13, 'fig1_yiq_front_listing' 14, 'fig1_yiq_specular' 15, 'former_complex_attenuation_several' 16, 'former_course_textured_highlight' 17, 'former_linear_attenuation_several' 18, 'former_yiq_saturated_attenuated' 19, 'forsyth_bidirectional' 20, 'forsyth_hemispherical' 21, 'forsyth_lambert' 22, 'forsyth_trilight' 23, 'forsyth_wrap_around' 24, 'light_ambient_only' 25, 'light_directional' 26, 'light_point_attenuation' 27, 'light_spot' 28, 'lights_several' 29, 'luma_only_cie_lstar_lambert' 30, 'luma_only_cie_lstar_wrap_around' 31, 'luma_only_yiq_lambert' 32, 'luma_only_yiq_trilight' 33, 'mesh_boxtextured_glb' 34, 'mesh_boxtextured_gltf' 35, 'mesh_objects_textured' 36, 'mesh_objects_transformed_untextured' 37, 'mesh_spider_obj' 38, 'mesh_spider_obj_untextured' 39, 'mesh_suzanne_gltf_untextured' 40, 'mesh_suzanne_obj_untextured' 41, 'mesh_wuson_obj' 42, 'mesh_wuson_ply' 43, 'mesh_wuson_stl' 44, 'minnaert_knot' 45, 'minnaert_suzanne' 46, 'object_materials' 47, 'oren_nayar_cycles_knot' 48, 'oren_nayar_cycles_suzanne' 49, 'oren_nayar_qualitative_knot' 50, 'oren_nayar_qualitative_suzanne' 51, 'shading_flat' 52, 'shading_gouraud' 53, 'shading_phong' 54, 'table2_knot_phong' 55, 'table2_knot_yiq' 56, 'table2_knot_yiq_listing' 57, 'texture16_bilinear_37x23' 58, 'texture16_nearest_37x23' 59)
plot 'p999.dat' using 2 title 'reference-povray', '' using 3 title 'reference-blender', '' using 4 title 'reference-eevee', '' using 5 title 'reference-gl', '' using 6 title 'reference-paper-listing', '' using 7 title 'povray-blender', '' using 8 title 'povray-eevee', '' using 9 title 'povray-gl', '' using 10 title 'povray-paper-listing', '' using 11 title 'blender-eevee', '' using 12 title 'blender-gl', '' using 13 title 'blender-paper-listing', '' using 14 title 'eevee-gl', '' using 15 title 'eevee-paper-listing', '' using 16 title 'gl-paper-listing'
