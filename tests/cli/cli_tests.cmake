# End-to-end tests of the `lightlab` command line: exit status, the one-line
# error contract, and real output files.
set(LL $<TARGET_FILE:lightlab>)
set(SCENES ${PROJECT_SOURCE_DIR}/data/scenes)
set(OUT ${CMAKE_CURRENT_BINARY_DIR}/cli_out)
file(MAKE_DIRECTORY ${OUT})
set(EXPECT_ERROR ${CMAKE_CURRENT_LIST_DIR}/expect_error.sh)

# A bad-input case: NAME, regex the single stderr line must match, then the arguments.
function(lightlab_error_test name regex)
  add_test(NAME cli.error.${name}
           COMMAND bash ${EXPECT_ERROR} "${regex}" ${OUT}/${name}.png -- ${LL} ${ARGN})
endfunction()

lightlab_error_test(unknown_option "^lightlab: error: The following argument was not expected: --bogus \\(see lightlab render --help\\)$"
                    render ${SCENES}/cornell_box.json --bogus)
lightlab_error_test(missing_scene "^lightlab: error: .*/nope\\.json: no such scene file$" render ${SCENES}/nope.json -o ${OUT}/missing_scene.png)
lightlab_error_test(malformed_json "malformed_json\\.json:6:5: malformed JSON: syntax error while parsing object - unexpected string literal; expected '}' \\(a missing comma before it\\?\\)$"
                    render ${SCENES}/tests/bad/malformed_json.json -o ${OUT}/malformed_json.png)
lightlab_error_test(unknown_key "unknown_key\\.json:6:5: unknown key 'fovy' in scene\\.camera \\(allowed: eye, target, up, fov_y_deg, width, height\\)$"
                    render ${SCENES}/tests/bad/unknown_key.json -o ${OUT}/unknown_key.png)
lightlab_error_test(wrong_type "wrong_type\\.json:27:7: scene\\.objects\\[0\\]\\.radius must be a number, got a string$"
                    render ${SCENES}/tests/bad/wrong_type.json -o ${OUT}/wrong_type.png)
lightlab_error_test(negative_radius "negative_radius\\.json:[0-9]+:[0-9]+: .*radius must be > 0"
                    render ${SCENES}/tests/bad/negative_radius.json -o ${OUT}/negative_radius.png)
lightlab_error_test(unknown_material "unknown_material\\.json:[0-9]+:[0-9]+: unknown material 'gold' \\(defined: "
                    render ${SCENES}/tests/bad/unknown_material.json -o ${OUT}/unknown_material.png)
lightlab_error_test(missing_mesh "missing_mesh\\.json:[0-9]+:[0-9]+: mesh file not found: /.*does_not_exist\\.ply"
                    render ${SCENES}/tests/bad/missing_mesh.json -o ${OUT}/missing_mesh.png)
lightlab_error_test(unknown_technique "unknown technique 'phong' \\(known: blinn-phong, raycast"
                    render ${SCENES}/cornell_box.json -t phong -o ${OUT}/unknown_technique.png)
lightlab_error_test(unknown_accelerator "unknown accelerator 'kd' \\(known: none"
                    render ${SCENES}/cornell_box.json -a kd -o ${OUT}/unknown_accelerator.png)
lightlab_error_test(out_of_range "^lightlab: error: technique 'raycast' parameter 'light_samples' = 0 is out of range \\[1, 1024\\]$"
                    render ${SCENES}/cornell_box.json --set light_samples=0 -o ${OUT}/out_of_range.png)
lightlab_error_test(unknown_parameter "has no parameter 'samples' \\(parameters: light_samples"
                    render ${SCENES}/cornell_box.json --set samples=4 -o ${OUT}/unknown_parameter.png)
lightlab_error_test(bad_choice "unknown value 'gpu' \\(one of: auto, student, framework\\)"
                    render ${SCENES}/cornell_box.json --set intersection=gpu -o ${OUT}/bad_choice.png)
lightlab_error_test(bad_extension "unknown image extension '\\.bmp' \\(allowed: \\.png, \\.jpg, \\.hdr, \\.pfm\\)"
                    render ${SCENES}/tests/sphere_point_light.json -o ${OUT}/bad_extension.bmp)
lightlab_error_test(spp_range "--spp: Value 0 not in range"
                    render ${SCENES}/cornell_box.json --spp 0 -o ${OUT}/spp_range.png)

# The rest of the README's bad-input table (tests/cli/bad_input/): one line each, no image written.
set(BAD_INPUT ${CMAKE_CURRENT_LIST_DIR}/bad_input)
lightlab_error_test(mesh_nan_coordinate "nan_mesh\\.json:5:52: /.*/nan_vertex\\.stl: vertex 1 has a non-finite coordinate$"
                    render ${BAD_INPUT}/nan_mesh.json -o ${OUT}/mesh_nan_coordinate.png)
lightlab_error_test(mesh_empty "empty_mesh\\.json:5:52: /.*/empty\\.off: the mesh has no faces$"
                    render ${BAD_INPUT}/empty_mesh.json -o ${OUT}/mesh_empty.png)
lightlab_error_test(zero_area_light "zero_area_light\\.json:5:15: emissive object 'triangles 0' has zero area: it cannot light anything$"
                    render ${BAD_INPUT}/zero_area_light.json -o ${OUT}/zero_area_light.png)
lightlab_error_test(camera_up_parallel "up_parallel\\.json:2:3: camera up is parallel to the view direction \\(target - eye\\); choose another up$"
                    render ${BAD_INPUT}/up_parallel.json -o ${OUT}/camera_up_parallel.png)
lightlab_error_test(number_beyond_float "huge_number\\.json:5:75: scene\\.objects\\[0\\]\\.radius = 1e\\+39 is not a finite float \\(\\|x\\| <= 3\\.4e38\\)$"
                    render ${BAD_INPUT}/huge_number.json -o ${OUT}/number_beyond_float.png)
# Issue 25: inputs that are too big, not text, or beyond the scene limits (the fuzzers' regression inputs).
set(REGRESSIONS ${PROJECT_SOURCE_DIR}/tests/fuzz/regressions/scene_json)
execute_process(COMMAND truncate -s 2G ${OUT}/two_gigabytes.json)  # sparse: no disk space
lightlab_error_test(scene_file_too_big "two_gigabytes\\.json: this scene file is 2\\.0 GB; LightLab reads a scene file of at most 64 MB \\(is it the right file\\?\\)$"
                    render ${OUT}/two_gigabytes.json -o ${OUT}/scene_file_too_big.png)
lightlab_error_test(nul_bytes_after_the_scene "trailing_nul_bytes\\.json:6:1: a NUL byte \\(0x00\\): a scene file is text, and this one holds binary data from here on$"
                    render ${REGRESSIONS}/trailing_nul_bytes.json -o ${OUT}/nul_bytes_after_the_scene.png)
lightlab_error_test(latin1_scene "latin1_description\\.json:2:19: malformed JSON: a byte that is not UTF-8 \\(the file was saved in another encoding, such as Latin-1: save it as UTF-8\\)$"
                    render ${REGRESSIONS}/latin1_description.json -o ${OUT}/latin1_scene.png)
lightlab_error_test(overflow "sphere_at_1e38\\.json:4:13: object 'sphere 0' reaches 1e\\+38 scene units: overflow \\(allowed: within \\+-1e\\+08 units, where float arithmetic stays exact enough; scale the scene down\\)$"
                    render ${REGRESSIONS}/sphere_at_1e38.json -o ${OUT}/overflow.png)
lightlab_error_test(obj_bad_face_index "obj_bad_index\\.obj: face 1 uses vertex 4, but the file has 3$"
                    render ${SCENES}/tests/bad/obj_bad_index.obj -o ${OUT}/obj_bad_face_index.png)

# Renders that must succeed and write their files.
# Without -o the image goes to out/SCENE-TECHNIQUE.png in the working directory (issue 27's command, smaller).
file(MAKE_DIRECTORY ${OUT}/default_output)
add_test(NAME cli.render.default_output_path
         COMMAND ${LL} --quiet render ${SCENES}/cornell_box_spectral.json -t path --set spectral=true
                 --width 32 --spp 2
         WORKING_DIRECTORY ${OUT}/default_output)
set_tests_properties(cli.render.default_output_path PROPERTIES
                     PASS_REGULAR_EXPRESSION "^wrote out/cornell_box_spectral-path\\.png \\(32x32, 2 spp, path")
add_test(NAME cli.render.cornell_box
         COMMAND ${LL} --quiet render ${SCENES}/cornell_box.json -t raycast -o ${OUT}/cornell.png
                 --stats ${OUT}/cornell.json)
set_tests_properties(cli.render.cornell_box PROPERTIES PASS_REGULAR_EXPRESSION "wrote .*cornell\\.png \\(512x512")
add_test(NAME cli.render.cornell_box_stats
         COMMAND ${Python3_EXECUTABLE} -c "import json,sys; s=json.load(open(sys.argv[1])); r=s['rays']; \
assert r['camera']==512*512, r; assert r['shadow']>0 and r['reflection']==0 and r['refraction']==0, r; \
assert s['non_finite_samples']==0 and s['missing_tasks']=={}, s; print('ok', r)" ${OUT}/cornell.json)
set_tests_properties(cli.render.cornell_box_stats PROPERTIES DEPENDS cli.render.cornell_box)
add_test(NAME cli.compare.identical
         COMMAND ${LL} compare ${OUT}/cornell.png ${OUT}/cornell.png --metric rmse --max 0 --diff ${OUT}/diff.png)
set_tests_properties(cli.compare.identical PROPERTIES DEPENDS cli.render.cornell_box PASS_REGULAR_EXPRESSION "rmse 0")
# The white furnace's analytic answer, read as `compare` prints an image's mean: Le / (1 - a) = 5 within 1 %.
add_test(NAME cli.render.furnace
         COMMAND ${LL} --quiet render ${SCENES}/tests/furnace.json -t path --spp 64 --set max_depth=256 -o ${OUT}/furnace.pfm)
add_test(NAME cli.compare.furnace_mean COMMAND ${LL} compare ${OUT}/furnace.pfm ${OUT}/furnace.pfm)
set_tests_properties(cli.compare.furnace_mean PROPERTIES DEPENDS cli.render.furnace
                     PASS_REGULAR_EXPRESSION "mean +(4\\.9[5-9]|5\\.0[0-4])[0-9]* \\(reference")
add_test(NAME cli.render.obj_scene
         COMMAND ${LL} --quiet render ${SCENES}/tests/obj_scene/cube.obj --width 64 -o ${OUT}/cube.pfm)
add_test(NAME cli.info.cornell_json
         COMMAND ${LL} info ${SCENES}/cornell_box.json --json)
set_tests_properties(cli.info.cornell_json PROPERTIES PASS_REGULAR_EXPRESSION "\"soft-shadows\"")
add_test(NAME cli.trace.pixel_json
         COMMAND ${LL} trace ${SCENES}/cornell_box.json --pixel 256 480 --json)
set_tests_properties(cli.trace.pixel_json PROPERTIES PASS_REGULAR_EXPRESSION "\"object\": \"floor\"")
# Radiosity from the command line: every patch and the solver's history as JSON, the residual plot.
add_test(NAME cli.radiosity.cornell_box
         COMMAND ${LL} --quiet radiosity ${SCENES}/cornell_box.json --set patch_size=0.1 --set hemicube_res=16
                 --json ${OUT}/radiosity.json --plot ${OUT}/radiosity.svg)
set_tests_properties(cli.radiosity.cornell_box PROPERTIES PASS_REGULAR_EXPRESSION "converged after [0-9]+ iterations")
add_test(NAME cli.radiosity.cornell_box_json
         COMMAND ${Python3_EXECUTABLE} -c "import json,sys; s=json.load(open(sys.argv[1])); p=s['patches']; \
assert len(p)>300, len(p); assert set(p[0])>={'id','object','area','centre','normal','emission','reflectance','radiosity'}; \
h=s['solver']['history']; assert s['solver']['converged'] and h[-1]['residual']<h[0]['residual'], h; \
assert abs(s['form_factors']['row_sum']['max']-1)<0.01, s['form_factors']; \
assert open(sys.argv[2]).read().startswith('<svg'); print('ok', len(p), 'patches')" ${OUT}/radiosity.json ${OUT}/radiosity.svg)
set_tests_properties(cli.radiosity.cornell_box_json PROPERTIES DEPENDS cli.radiosity.cornell_box)
lightlab_error_test(radiosity_bad_solver "parameter 'solver': unknown value 'cg' \\(one of: gauss-seidel, jacobi, direct, southwell, hierarchical\\)"
                    radiosity ${SCENES}/cornell_box.json --set solver=cg)
lightlab_error_test(radiosity_direct_too_big "solver 'direct': [0-9]+ patches, more than the dense LU's limit of 3000"
                    --quiet radiosity ${SCENES}/cornell_box.json --set solver=direct --set patch_size=0.03 --set hemicube_res=4)
add_test(NAME cli.help COMMAND ${LL} --help)
set_tests_properties(cli.help PROPERTIES PASS_REGULAR_EXPRESSION "render.*info.*trace.*compare.*radiosity")
lightlab_error_test(compare_sizes "image sizes differ" compare ${OUT}/cube.pfm ${OUT}/cornell.png)
set_tests_properties(cli.error.compare_sizes PROPERTIES DEPENDS "cli.render.obj_scene;cli.render.cornell_box")
lightlab_error_test(compare_missing "nothere\\.png: no such image file" compare ${OUT}/nothere.png ${OUT}/cornell.png)

# The GUI's bad input: the same one-line contract, checked before any window opens.
if(LIGHTLAB_WITH_GUI)
  add_test(NAME cli.error.gui_without_display
           COMMAND env -u DISPLAY bash ${EXPECT_ERROR} "cannot open a window \\(GLFW error [0-9]+: .*DISPLAY.*\\); without a display use"
                   "" -- ${LL} gui ${SCENES}/cornell_box.json)
  add_test(NAME cli.error.gpu_technique_without_display
           COMMAND env -u DISPLAY bash ${EXPECT_ERROR} "renders with OpenGL and needs a display \\(GLFW error"
                   ${OUT}/gpu.png -- ${LL} render ${SCENES}/cornell_box.json -t blinn-phong-gl -o ${OUT}/gpu.png)
  lightlab_error_test(gui_missing_preset "nope\\.json: no such preset file" gui --preset ${SCENES}/nope.json)
  lightlab_error_test(gui_missing_scene "nope\\.json: no such scene file" gui ${SCENES}/nope.json)
  lightlab_error_test(gui_scene_as_preset "cornell_box\\.json:1:1: not a LightLab view preset: it needs \"lightlab_preset\": 1"
                      gui --preset ${SCENES}/cornell_box.json)
  lightlab_error_test(gui_bad_preset_value "bad_preset\\.json:[0-9]+:[0-9]+: .*light_samples.*\\[1, 1024\\]"
                      gui --preset ${PROJECT_SOURCE_DIR}/tests/gui/bad_preset.json)
endif()

# Grading: unknown assignments and tasks, and broken grading specs, named with file:line:col.
set(GRADING_BAD ${PROJECT_SOURCE_DIR}/tests/grading/bad)
lightlab_error_test(grade_unknown_assignment "unknown assignment 'A9' \\(allowed: A1 \\(a1_rasterizer\\), A2"
                    grade A9 --report ${OUT}/grade_unknown)
lightlab_error_test(grade_unknown_task "no task 'A2.9' in .*a2_raycasting/grading\\.json \\(allowed: A2.1, A2.2"
                    grade A2 --task A2.9 --report ${OUT}/grade_unknown_task)
lightlab_error_test(grade_unknown_kind "unknown_kind\\.json:6:[0-9]+: unknown test kind 'exam' \\(allowed: unit, image, complexity\\)"
                    grade ${GRADING_BAD}/unknown_kind.json --report ${OUT}/grade_bad)
lightlab_error_test(grade_unknown_reference "unknown_reference\\.json:6:[0-9]+: no reference image 'teapot\\.hdr' in .*\\(allowed: sphere_point_light\\.hdr"
                    grade ${GRADING_BAD}/unknown_reference.json --report ${OUT}/grade_bad)
lightlab_error_test(grade_missing_task_tests "grade: no task tests at /nope \\(build them"
                    grade A2 --task-tests /nope --report ${OUT}/grade_bad)

# Study: accuracy against time.
add_test(NAME cli.study_error_falls_with_light_samples
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/study_test.sh ${LL} ${OUT}/study)
# study effects on a scene named as an argument, small: every technique against ground truth, and the table of the
# fastest technique within the tolerance and 10x and 100x it.
add_test(NAME cli.study_effects
         COMMAND ${LL} --quiet study effects ${SCENES}/whitted_1980.json --width 32 --reference-spp 64
                 --out ${OUT}/study_effects)
set_tests_properties(cli.study_effects PROPERTIES PASS_REGULAR_EXPRESSION
                     "whitted +4 .*relMSE 0\\.001 +relMSE 0\\.01 +relMSE 0\\.1.*whitted_1980\\.json .*wrote .*effects\\.csv")
lightlab_error_test(study_two_scenes "study: one scene or built-in study at a time"
                    study ${SCENES}/cornell_box.json ${SCENES}/whitted_1980.json --knob spp=1,2 --out ${OUT}/study_bad)
lightlab_error_test(study_bad_knob "study: --knob must be NAME=v1,v2,... \\(got 'spp'\\)"
                    study ${SCENES}/cornell_box.json --knob spp --out ${OUT}/study_bad)
lightlab_error_test(study_unknown_parameter "technique 'raycast' has no parameter 'depth' \\(parameters: "
                    study ${SCENES}/cornell_box.json --knob depth=1,2 --out ${OUT}/study_bad)

# Slide decks: a bad deck or preset block is one line naming deck:line (or preset:line:col) and what is allowed.
set(BAD_DECKS ${PROJECT_SOURCE_DIR}/tests/slides/bad)
lightlab_error_test(slides_missing_deck "nope\\.md: no such slide deck" slides check ${BAD_DECKS}/nope.md)
lightlab_error_test(slides_unknown_key "unknown_key\\.md:9:2: unknown key 'pane' in preset \\(allowed: lightlab_preset, description, scene"
                    slides check ${BAD_DECKS}/unknown_key.md)
lightlab_error_test(slides_unknown_technique "unknown_technique\\.md:5:13: unknown technique 'phong' \\(known: blinn-phong, raycast"
                    slides check ${BAD_DECKS}/unknown_technique.md)
lightlab_error_test(slides_malformed_json "malformed_json\\.md:7:2: malformed JSON: .*missing comma"
                    slides check ${BAD_DECKS}/malformed_json.md)
lightlab_error_test(slides_unterminated_block "unterminated\\.md:3: unterminated preset block \\(close it with ```\\)"
                    slides check ${BAD_DECKS}/unterminated.md)
lightlab_error_test(slides_block_option "block_option\\.md:3: unknown preset block option 'live' \\(allowed: none"
                    slides check ${BAD_DECKS}/block_option.md)
lightlab_error_test(slides_two_presets "two_presets\\.md:7: a second preset block in the slide of line 1 \\(one per slide"
                    slides check ${BAD_DECKS}/two_presets.md)
lightlab_error_test(slides_two_lines "two_lines\\.md:3: a preset block holds a JSON view preset or one preset file path, not 2 lines"
                    slides check ${BAD_DECKS}/two_lines.md)
lightlab_error_test(slides_empty_block "empty_block\\.md:3: empty preset block \\(allowed: a JSON view preset, or one line naming a preset file\\)"
                    slides check ${BAD_DECKS}/empty_block.md)
lightlab_error_test(slides_missing_preset_file "missing_preset_file\\.md:4: preset file '\\.\\./\\.\\./\\.\\./data/presets/nope\\.json' not found"
                    slides check ${BAD_DECKS}/missing_preset_file.md)
lightlab_error_test(slides_missing_scene "missing_scene\\.md:4: the preset's scene '.*data/scenes/nope\\.json' not found"
                    slides check ${BAD_DECKS}/missing_scene.md)
lightlab_error_test(slides_build_needs_out "--out is required" slides build ${BAD_DECKS}/unknown_key.md)
if(LIGHTLAB_WITH_GUI)
  lightlab_error_test(gui_slides_bad_deck "unknown_key\\.md:9:2: unknown key 'pane' in preset"
                      gui --slides ${BAD_DECKS}/unknown_key.md)
endif()
# A system small enough to check by hand: the white furnace as 6 quad patches. --json writes F (rows sum
# to 1: a closed room, normalised hemicube) and the bounce terms K^n E, which sum to the solution.
add_test(NAME cli.radiosity.furnace_matrix_and_bounces
         COMMAND ${LL} --quiet radiosity ${SCENES}/tests/furnace.json --set patch_size=1 --set solver=direct
                 --json ${OUT}/furnace_radiosity.json)
add_test(NAME cli.radiosity.furnace_matrix_and_bounces_json
         COMMAND ${Python3_EXECUTABLE} -c "import json,sys,math; s=json.load(open(sys.argv[1])); \
rows=s['form_factors']['matrix']['rows']; assert len(rows)==6, len(rows); \
assert all(abs(sum(f for j,f in r)-1)<1e-5 for r in rows), [sum(f for j,f in r) for r in rows]; \
b=s['bounces']; total=[sum(t['radiosity'][i][0] for t in b) for i in range(6)]; \
assert all(len(p['corners'])==4 for p in s['patches']); \
exact=math.pi/(1-0.8); assert all(abs(x-exact)<1e-3*exact for x in total), (len(b), total); \
assert all(abs(p['radiosity'][0]-exact)<1e-4*exact for p in s['patches']); \
assert s['solver']['converged'] and s['solver']['failure']=='', s['solver']; print('ok', len(b), 'bounce terms')"
                 ${OUT}/furnace_radiosity.json)
set_tests_properties(cli.radiosity.furnace_matrix_and_bounces_json PROPERTIES DEPENDS cli.radiosity.furnace_matrix_and_bounces)
# Albedo 1 in a closed box: singular. Said on stderr in one line, and in the JSON.
add_test(NAME cli.radiosity.singular_system_is_reported
         COMMAND ${LL} --quiet radiosity ${SCENES}/tests/closed_box_albedo_one.json --set patch_size=1 --set solver=direct)
set_tests_properties(cli.radiosity.singular_system_is_reported PROPERTIES PASS_REGULAR_EXPRESSION
  "lightlab: radiosity \\(direct, 6 patches\\) NOT converged: the system is singular or nearly so \\(reciprocal condition number [-0-9.e]+, residual [-0-9.e]+\\); rho F is not a contraction: row [0-9]+ of rho F sums to 1 \\(reflectance 1 in a closed scene: light never leaves\\)")
# Hierarchical radiosity (Hanrahan et al. 1991): elements and links in the JSON, links far fewer than leaves^2.
add_test(NAME cli.radiosity.hierarchical
         COMMAND ${LL} --quiet radiosity ${SCENES}/cornell_box.json --set solver=hierarchical --set link_epsilon=1e-4
                 --json ${OUT}/hierarchical.json)
set_tests_properties(cli.radiosity.hierarchical PROPERTIES PASS_REGULAR_EXPRESSION
  "hierarchical radiosity \\(link_epsilon 0.0001\\): 32 base patches, [0-9]+ elements, [0-9]+ leaves, [0-9]+ links")
add_test(NAME cli.radiosity.hierarchical_json
         COMMAND ${Python3_EXECUTABLE} -c "import json,sys,math; s=json.load(open(sys.argv[1])); h=s['hierarchical']; \
assert h['leaves']==len(s['patches'])>1000 and h['elements']>h['leaves'], h; assert h['links']<0.05*h['leaves']**2, h; \
assert s['solver']['converged'] and s['solver']['failure']=='', s['solver']; \
assert all(math.isfinite(c) for p in s['patches'] for c in p['radiosity']); print('ok', h)" ${OUT}/hierarchical.json)
set_tests_properties(cli.radiosity.hierarchical_json PROPERTIES DEPENDS cli.radiosity.hierarchical)
# Progressive refinement's history: shots and unshot power after 32, 64, 128, ... shots, falling to the tolerance.
add_test(NAME cli.radiosity.progressive_history
         COMMAND ${LL} --quiet radiosity ${SCENES}/cornell_box.json --set progressive=true --set patch_size=0.1
                 --set hemicube_res=16 --json ${OUT}/progressive.json)
set_tests_properties(cli.radiosity.progressive_history PROPERTIES PASS_REGULAR_EXPRESSION
  "progressive refinement: [0-9]+ patches, [0-9]+ shots, unshot [-0-9.e]+ of the emitted power \\(converged\\)")
add_test(NAME cli.radiosity.progressive_history_json
         COMMAND ${Python3_EXECUTABLE} -c "import json,sys; s=json.load(open(sys.argv[1])); p=s['progressive']; h=p['history']; \
assert p['converged'] and h[0]['shots']==32 and len(h)>3, p; \
assert all(b['shots']>a['shots'] and b['unshot_fraction']<=a['unshot_fraction'] for a,b in zip(h,h[1:])), h; \
assert h[-1]['unshot_fraction']<=1e-4 and len(s['patches'])>300; print('ok', len(h), 'steps')" ${OUT}/progressive.json)
set_tests_properties(cli.radiosity.progressive_history_json PROPERTIES DEPENDS cli.radiosity.progressive_history)
# The measured effects: info's probe and verdicts, render's effects=measured (tests/cli/effects_test.py).
add_test(NAME cli.effects_measured
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/effects_test.py ${LL} ${SCENES} ${OUT})
