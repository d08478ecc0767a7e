# Plots of the vein quick runs (scripts/post/plot_vein_*.py, and plot_fields.py):
# each script writes its PNG (or GIF) into ${DMHS_VEIN_OUT}/plots (emptied first by
# validation_vein_plots_clean) and fails on a missing or incomplete input;
# validation_vein_plots_check then asserts that every file exists and is larger
# than 10 kB. The file that includes
# this one defines DMHS_PYTHON, DMHS_VEIN_OUT and the fixtures vein_quick and
# vein_quick_2ranks.
#
# Run as a script, it is that check:
#   cmake -P vein_plots.cmake FILE...   (exit 1 when a file is missing or <= 10 kB)
if(CMAKE_SCRIPT_MODE_FILE)
  math(EXPR last "${CMAKE_ARGC} - 1")
  if(last LESS 3)
    message(FATAL_ERROR "usage: cmake -P vein_plots.cmake PNG...")
  endif()
  foreach(i RANGE 3 ${last}) # CMAKE_ARGV0..2: cmake -P <this file>
    set(png "${CMAKE_ARGV${i}}")
    if(NOT EXISTS "${png}")
      message(SEND_ERROR "${png}: missing")
      continue()
    endif()
    file(SIZE "${png}" size)
    if(size LESS_EQUAL 10240)
      message(SEND_ERROR "${png}: ${size} bytes, not larger than 10 kB")
    else()
      message(STATUS "${png}: ${size} bytes")
    endif()
  endforeach()
  return()
endif()

# test/CMakeLists.txt includes every validation/*.cmake: without the vein
# outputs defined yet this is a no-op, and the tests are added once
if(NOT DEFINED DMHS_VEIN_OUT OR NOT DEFINED DMHS_PYTHON)
  return()
endif()
include_guard(GLOBAL)

set(DMHS_VEIN_PLOTS ${DMHS_VEIN_OUT}/plots)
set(DMHS_VEIN_POST ${PROJECT_SOURCE_DIR}/scripts/post)
add_test(NAME validation_vein_plots_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${DMHS_VEIN_PLOTS})
set_tests_properties(validation_vein_plots_clean PROPERTIES LABELS validation TIMEOUT 30
                     FIXTURES_SETUP vein_plots_clean)

# four panels of the liquid at the peak flow (shear rate, |sigma|, pressure force, |v|)
add_test(NAME validation_vein_plot_fields
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_fields.py ${DMHS_VEIN_OUT}/quick
                 --out ${DMHS_VEIN_PLOTS}/vein_fields.png)
# the sinus liquid coloured by displacement, once per period
add_test(NAME validation_vein_plot_sinus
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_sinus.py ${DMHS_VEIN_OUT}/quick
                 --out ${DMHS_VEIN_PLOTS}/vein_sinus.png)
# the measurement point's displacement and stress, inlet velocities, tip gap against t
add_test(NAME validation_vein_plot_probe
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_probe.py ${DMHS_VEIN_OUT}/quick
                 --out ${DMHS_VEIN_PLOTS}/vein_probe.png)
# the annotated geometry at t = 0 and the leaflet root
add_test(NAME validation_vein_plot_geometry
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_geometry.py ${DMHS_VEIN_OUT}/quick
                 --out ${DMHS_VEIN_PLOTS}/vein_geometry.png)
# the upper leaflet against a static cantilever under the liquid's pressure difference
add_test(NAME validation_vein_beam
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/vein_beam.py ${DMHS_VEIN_OUT}/quick --check)
set_tests_properties(validation_vein_beam PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED vein_quick)
foreach(p fields sinus probe geometry)
  set_tests_properties(validation_vein_plot_${p} PROPERTIES LABELS validation TIMEOUT 120
                       FIXTURES_REQUIRED "vein_quick;vein_plots_clean" FIXTURES_SETUP vein_plots)
endforeach()
# the study figures over the two quick runs (1 and 2 ranks)
add_test(NAME validation_vein_plot_study
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_study.py ${DMHS_VEIN_OUT}/quick
                 ${DMHS_VEIN_OUT}/quick-2ranks --out ${DMHS_VEIN_PLOTS}/)
set_tests_properties(validation_vein_plot_study PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED "vein_quick;vein_quick_2ranks;vein_plots_clean" FIXTURES_SETUP vein_plots)

# inlet velocities of several runs against time (here the two quick runs)
add_test(NAME validation_vein_plot_inlet
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_inlet.py ${DMHS_VEIN_OUT}/quick
                 ${DMHS_VEIN_OUT}/quick-2ranks --out ${DMHS_VEIN_PLOTS}/vein_inlet.png)
set_tests_properties(validation_vein_plot_inlet PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED "vein_quick;vein_quick_2ranks;vein_plots_clean" FIXTURES_SETUP vein_plots)

# velocity vectors in the sinus (Fig. 4.5) and the leaflets at closure, per run (Fig. 4.8)
add_test(NAME validation_vein_plot_vectors
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_vectors.py ${DMHS_VEIN_OUT}/quick
                 --out ${DMHS_VEIN_PLOTS}/vein_vectors.png)
add_test(NAME validation_vein_plot_closure
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_closure.py ${DMHS_VEIN_OUT}/quick
                 ${DMHS_VEIN_OUT}/quick-2ranks --out ${DMHS_VEIN_PLOTS}/vein_closure.png)
set_tests_properties(validation_vein_plot_vectors validation_vein_plot_closure PROPERTIES LABELS validation
                     TIMEOUT 120 FIXTURES_REQUIRED "vein_quick;vein_quick_2ranks;vein_plots_clean"
                     FIXTURES_SETUP vein_plots)
# a missing run directory: exit status 1 and one line naming it
foreach(p fields sinus vectors closure convergence)
  add_test(NAME validation_vein_plot_${p}_missing
           COMMAND bash ${PROJECT_SOURCE_DIR}/test/cli/expect_fail.sh "no-such-run: no such directory" --lines 1 --
                   ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_${p}.py ${DMHS_VEIN_OUT}/no-such-run)
  set_tests_properties(validation_vein_plot_${p}_missing PROPERTIES LABELS validation TIMEOUT 60)
endforeach()

# one case at several spacings on common axes (here the two quick runs at one spacing)
add_test(NAME validation_vein_plot_convergence
         COMMAND ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_vein_convergence.py ${DMHS_VEIN_OUT}/quick
                 ${DMHS_VEIN_OUT}/quick-2ranks --out ${DMHS_VEIN_PLOTS}/vein_convergence.png)
set_tests_properties(validation_vein_plot_convergence PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED "vein_quick;vein_quick_2ranks;vein_plots_clean" FIXTURES_SETUP vein_plots)

# scripts/post/plot_fields.py, the general field plotter, on the quick run: one field at one
# time as a PNG, a time series as a GIF (PillowWriter: not run when this Python has no
# pillow), the field list with units; and its clean failures (exit status 1, one line): a
# missing directory, a directory without snapshots, an unknown field (naming the fields),
# a time outside the run
set(DMHS_PLOT_FIELDS ${DMHS_PYTHON} ${DMHS_VEIN_POST}/plot_fields.py)
add_test(NAME validation_plot_fields_png
         COMMAND ${DMHS_EXPECT_OUTPUT} "fields_p\\.png: p \\[Pa\\] at t = 0\\.(2|199)"
                 -- ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/quick --field p --time 0.2
                 --out ${DMHS_VEIN_PLOTS}/fields_p.png)
add_test(NAME validation_plot_fields_gif
         COMMAND ${DMHS_EXPECT_OUTPUT} "fields_speed\\.gif: 11 frame\\(s\\) of speed \\[m/s\\], t = 0 \\.\\. 0\\.5"
                 -- ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/quick --field speed --every 5
                 --animate ${DMHS_VEIN_PLOTS}/fields_speed.gif)
add_test(NAME validation_plot_fields_list
         COMMAND ${DMHS_EXPECT_OUTPUT} "p +\\[Pa\\] +scalar.* v +\\[m/s\\] +vector: v \\(magnitude\\), v_x, v_y"
                 -- ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/quick --list --time 0.25)
set_tests_properties(validation_plot_fields_png validation_plot_fields_gif validation_plot_fields_list
                     PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED "vein_quick;vein_plots_clean" FIXTURES_SETUP vein_plots)
execute_process(COMMAND ${DMHS_PYTHON} -c "import PIL" RESULT_VARIABLE _pillow OUTPUT_QUIET ERROR_QUIET)
if(NOT _pillow EQUAL 0)
  message(WARNING "${DMHS_PYTHON} cannot import PIL (pillow): validation_plot_fields_gif will not run "
    "(Debian: apt-get install python3-pil)")
  set_tests_properties(validation_plot_fields_gif PROPERTIES DISABLED TRUE)
endif()
add_test(NAME validation_plot_fields_missing_dir
         COMMAND ${DMHS_EXPECT_FAIL} "no-such-run: no such directory" --lines 1 --
                 ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/no-such-run --field p)
add_test(NAME validation_plot_fields_no_snapshot
         COMMAND ${DMHS_EXPECT_FAIL} "plot_fields.py: .*/input: no snapshot \\(no particles\\.xdmf, no snap_\\*\\.h5" --lines 1 --
                 ${DMHS_PLOT_FIELDS} ${PROJECT_SOURCE_DIR}/input --field p)
set_tests_properties(validation_plot_fields_missing_dir validation_plot_fields_no_snapshot PROPERTIES
                     LABELS validation TIMEOUT 60)
add_test(NAME validation_plot_fields_unknown_field
         COMMAND ${DMHS_EXPECT_FAIL} "unknown field 'pressure' in snap_[0-9]+\\.h5; fields: a, a_x, a_y, .* p, .* v, v_x, v_y" --lines 1 --
                 ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/quick --field pressure)
add_test(NAME validation_plot_fields_time_outside
         COMMAND ${DMHS_EXPECT_FAIL} "--time 9 s is outside the run: its [0-9]+ snapshot\\(s\\) span t = 0 \\.\\. 0\\.5" --lines 1 --
                 ${DMHS_PLOT_FIELDS} ${DMHS_VEIN_OUT}/quick --field p --time 9)
set_tests_properties(validation_plot_fields_unknown_field validation_plot_fields_time_outside PROPERTIES
                     LABELS validation TIMEOUT 60 FIXTURES_REQUIRED vein_quick)

add_test(NAME validation_vein_plots_check
         COMMAND ${CMAKE_COMMAND} -P ${CMAKE_CURRENT_LIST_FILE}
                 ${DMHS_VEIN_PLOTS}/vein_fields.png ${DMHS_VEIN_PLOTS}/vein_sinus.png
                 ${DMHS_VEIN_PLOTS}/vein_probe.png ${DMHS_VEIN_PLOTS}/vein_geometry.png
                 ${DMHS_VEIN_PLOTS}/vein_study_ka.png ${DMHS_VEIN_PLOTS}/vein_study_velocity.png
                 ${DMHS_VEIN_PLOTS}/vein_inlet.png ${DMHS_VEIN_PLOTS}/vein_convergence.png
                 ${DMHS_VEIN_PLOTS}/vein_vectors.png ${DMHS_VEIN_PLOTS}/vein_closure.png
                 ${DMHS_VEIN_PLOTS}/fields_p.png ${DMHS_VEIN_PLOTS}/fields_speed.gif)
set_tests_properties(validation_vein_plots_check PROPERTIES LABELS validation TIMEOUT 30
                     FIXTURES_REQUIRED vein_plots)

# the convergence plot's stretch table (a finer run stopped short of a cycle) on two made-up runs
add_test(NAME validation_vein_convergence_stretch
         COMMAND ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/test/validation/vein_stretch_check.py
                 ${DMHS_VEIN_POST}/plot_vein_convergence.py ${DMHS_VEIN_PLOTS}/stretch)
set_tests_properties(validation_vein_convergence_stretch PROPERTIES LABELS validation TIMEOUT 60
                     FIXTURES_REQUIRED vein_plots_clean)
