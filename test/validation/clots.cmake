# Clot agglomeration, quick case (input/vein-clot-quick.opts; doc/validation.md
# "Clot agglomeration"): on 3 ranks the two seeds' clots grow, clots.csv is
# consistent with the last snapshot (particle types, clot bonds), no NaN; on 1
# rank clots.csv and vein.csv are the same byte for byte; a checkpoint at
# t = 0.06 s (2 ranks; the step of an event, whose rebuild is pending) restarted
# on 1 rank too; the clot-size plot and the
# snapshot picture are drawn.
set(DMHS_CLOTS ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/clots.py --exe ${DMHS_EXE}
    --opts ${PROJECT_SOURCE_DIR}/input/vein-clot-quick.opts)
set(DMHS_CLOTS_OUT ${CMAKE_CURRENT_BINARY_DIR}/clots)
string(REPLACE ";" " " DMHS_CLOTS_MPIRUN "${DMHS_MPIRUN}")
add_test(NAME validation_clot_quick_3ranks
         COMMAND ${DMHS_CLOTS} --outdir ${DMHS_CLOTS_OUT}/quick-3ranks --ranks 3 --mpirun "${DMHS_CLOTS_MPIRUN}")
set_tests_properties(validation_clot_quick_3ranks PROPERTIES LABELS "validation;mpi" TIMEOUT 900 PROCESSORS 3
                     FIXTURES_SETUP clot_quick_3ranks)
add_test(NAME validation_clot_quick COMMAND ${DMHS_CLOTS} --outdir ${DMHS_CLOTS_OUT}/quick
                                            --compare ${DMHS_CLOTS_OUT}/quick-3ranks)
set_tests_properties(validation_clot_quick PROPERTIES LABELS validation TIMEOUT 300
                     FIXTURES_SETUP clot_quick FIXTURES_REQUIRED clot_quick_3ranks)
add_test(NAME validation_clot_restart
         COMMAND ${DMHS_CLOTS} --mode restart --outdir ${DMHS_CLOTS_OUT}/restart --ranks 2 --restart-ranks 1
                 --mpirun "${DMHS_CLOTS_MPIRUN}" --t-stop 0.06 --compare ${DMHS_CLOTS_OUT}/quick-3ranks)
set_tests_properties(validation_clot_restart PROPERTIES LABELS "validation;io;mpi" TIMEOUT 900 PROCESSORS 2
                     FIXTURES_REQUIRED clot_quick_3ranks)
add_test(NAME validation_clot_plot
         COMMAND ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/post/plot_clots.py ${DMHS_CLOTS_OUT}/quick
                 --out ${DMHS_CLOTS_OUT}/plots)
set_tests_properties(validation_clot_plot PROPERTIES LABELS validation TIMEOUT 120 FIXTURES_REQUIRED clot_quick
                     FIXTURES_SETUP clot_plot)
add_test(NAME validation_clot_plot_check
         COMMAND ${CMAKE_COMMAND} -P ${CMAKE_CURRENT_SOURCE_DIR}/validation/vein_plots.cmake
                 ${DMHS_CLOTS_OUT}/plots/clots.png ${DMHS_CLOTS_OUT}/plots/clots_snapshot.png)
set_tests_properties(validation_clot_plot_check PROPERTIES LABELS validation TIMEOUT 30 FIXTURES_REQUIRED clot_plot)

# option errors name the option (test/cli/cli.cmake defines dmhs_cli_fail)
set(DMHS_CLOT_OPTS -options_file ${PROJECT_SOURCE_DIR}/input/vein-clot-quick.opts -quiet)
dmhs_cli_fail(cli_clot_odd_seeds "-agglomeration_seeds takes pairs x,y" ${DMHS_CLOT_OPTS}
              -agglomeration_seeds 0.015 -output_dir ${DMHS_CLOTS_OUT}/cli-a)
dmhs_cli_fail(cli_clot_probability "-agglomeration_probability must lie in \\[0, 1\\]" ${DMHS_CLOT_OPTS}
              -agglomeration_probability 2 -output_dir ${DMHS_CLOTS_OUT}/cli-b)
dmhs_cli_fail(cli_clot_interval "-agglomeration_interval must be > 0" ${DMHS_CLOT_OPTS}
              -agglomeration_interval 0 -output_dir ${DMHS_CLOTS_OUT}/cli-c)
# without -vein_clots the module is not there: its options are not swallowed
dmhs_cli_fail(cli_clot_module_off "unknown or unused option -agglomeration_rmax"
              -options_file ${PROJECT_SOURCE_DIR}/input/vein-quick.opts -quiet -agglomeration_rmax 1e-3
              -output_dir ${DMHS_CLOTS_OUT}/cli-d)
