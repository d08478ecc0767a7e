# Solids: the two-layer mass-spring cantilever against Timoshenko
# beam theory (doc/theory.md, "Mass-spring leaflets as Timoshenko beams").
# Static tip deflection: long/stiff-angled (bending ~100 %) to short/soft-angled
# (shear 60-94 %), tolerance 1 %. First frequency: 0.5 % where bending
# dominates; 8 % for the short soft beam, where the Dunkerley combination of
# the bending and shear frequencies is only a lower bound.
set(DMHS_CANTILEVER ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/cantilever.py --exe ${DMHS_EXE})
foreach(case "41;0.01;0.01" "21;0.01;0.01" "11;0.001;0.01" "6;0.0001;0.01" "6;0.00001;0.01")
  list(GET case 0 n)
  list(GET case 1 ka)
  list(GET case 2 tol)
  add_test(NAME validation_cantilever_static_n${n}_ka${ka}
           COMMAND ${DMHS_CANTILEVER} --mode static --n ${n} --ka ${ka} --tol ${tol}
                   --outdir ${CMAKE_CURRENT_BINARY_DIR}/cantilever_static_n${n}_ka${ka})
  set_tests_properties(validation_cantilever_static_n${n}_ka${ka} PROPERTIES LABELS validation TIMEOUT 120)
endforeach()
foreach(case "41;0.01;0.005" "21;0.01;0.005" "11;0.001;0.005" "6;0.0001;0.08")
  list(GET case 0 n)
  list(GET case 1 ka)
  list(GET case 2 tol)
  add_test(NAME validation_cantilever_frequency_n${n}_ka${ka}
           COMMAND ${DMHS_CANTILEVER} --mode frequency --n ${n} --ka ${ka} --tol ${tol}
                   --outdir ${CMAKE_CURRENT_BINARY_DIR}/cantilever_frequency_n${n}_ka${ka})
  set_tests_properties(validation_cantilever_frequency_n${n}_ka${ka} PROPERTIES LABELS validation TIMEOUT 120)
endforeach()

# Flexible flap in a channel flow (quick variant, 0.8 s, ~25 s on one core;
# doc/validation.md "Flexible flap"). Measured: tip 0.125 of the height, mean
# of the last quarter vs the quarter before 0.44 %, wander over the last
# quarter 5.0 %, 0 crossings, slip on the faces 0.026 u_max. Tolerances ~2x.
add_test(NAME validation_flap_quick
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/flap.py --exe ${DMHS_EXE}
                 --opts ${PROJECT_SOURCE_DIR}/input/flap-quick.opts --outdir ${CMAKE_CURRENT_BINARY_DIR}/flap-quick
                 --drift 0.01 --steady 0.08 --slip 0.05 --min-deflection 0.05)
# its output is the reference of timestep_substeps_flap_quick (a fixture: that test then
# never compares with the output of an earlier or failed run)
set_tests_properties(validation_flap_quick PROPERTIES LABELS validation TIMEOUT 180 FIXTURES_SETUP flap_quick)

# The shipped flap (input/flap.opts, ~200 s on one core): label full. Measured
# (doc/validation.md): deflection 0.588 of the height, last-quarter wander
# 0.58 %, mean moved 1.4 % from the quarter before (still rising slowly),
# 0 crossings, slip 0.027 u_max. Tolerances ~2x.
add_test(NAME validation_flap_full
         COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/flap.py --exe ${DMHS_EXE}
                 --opts ${PROJECT_SOURCE_DIR}/input/flap.opts --outdir ${CMAKE_CURRENT_BINARY_DIR}/flap-full
                 --drift 0.03 --steady 0.015 --slip 0.05 --min-deflection 0.3)
set_tests_properties(validation_flap_full PROPERTIES LABELS full TIMEOUT 1800)

# Plots of these runs (scripts/post/plot_cantilever.py, plot_flap.py, which
# scripts/run.sh calls): each script runs on the output of a quick test above
# (its fixture), writes its PNGs into that run's directory (the default, as for
# a user's run; the PNGs are deleted first), and validation_solid_plots_check
# asserts that every PNG exists and is larger than 10 kB (vein_plots.cmake run
# as a script). The damped static run and the free oscillation draw the two
# variants of the cantilever's second panel.
set_tests_properties(validation_cantilever_static_n21_ka0.01 PROPERTIES FIXTURES_SETUP cantilever_static_n21)
set_tests_properties(validation_cantilever_frequency_n21_ka0.01 PROPERTIES FIXTURES_SETUP cantilever_frequency_n21)
set_tests_properties(validation_flap_quick PROPERTIES FIXTURES_SETUP flap_quick)
set(DMHS_SOLID_PNGS ${CMAKE_CURRENT_BINARY_DIR}/cantilever_static_n21_ka0.01/cantilever.png
    ${CMAKE_CURRENT_BINARY_DIR}/cantilever_frequency_n21_ka0.01/cantilever.png
    ${CMAKE_CURRENT_BINARY_DIR}/flap-quick/flap_history.png ${CMAKE_CURRENT_BINARY_DIR}/flap-quick/flap_flow.png)
add_test(NAME validation_solid_plots_clean COMMAND ${CMAKE_COMMAND} -E rm -f ${DMHS_SOLID_PNGS})
set_tests_properties(validation_solid_plots_clean PROPERTIES LABELS validation TIMEOUT 30
                     FIXTURES_SETUP solid_plots_clean)
foreach(mode static frequency)
  add_test(NAME validation_cantilever_${mode}_plot
           COMMAND ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/post/plot_cantilever.py
                   ${CMAKE_CURRENT_BINARY_DIR}/cantilever_${mode}_n21_ka0.01)
  set_tests_properties(validation_cantilever_${mode}_plot PROPERTIES LABELS validation TIMEOUT 120
                       FIXTURES_REQUIRED "cantilever_${mode}_n21;solid_plots_clean" FIXTURES_SETUP solid_plots)
endforeach()
add_test(NAME validation_flap_quick_plot
         COMMAND ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/post/plot_flap.py ${CMAKE_CURRENT_BINARY_DIR}/flap-quick)
set_tests_properties(validation_flap_quick_plot PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_REQUIRED "flap_quick;solid_plots_clean" FIXTURES_SETUP solid_plots)
add_test(NAME validation_solid_plots_check
         COMMAND ${CMAKE_COMMAND} -P ${CMAKE_CURRENT_LIST_DIR}/vein_plots.cmake ${DMHS_SOLID_PNGS})
set_tests_properties(validation_solid_plots_check PROPERTIES LABELS validation TIMEOUT 30
                     FIXTURES_REQUIRED solid_plots)
