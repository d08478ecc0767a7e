# Output at the end (test/io/final_output.sh): a run whose -t_end falls between
# output times writes its final state as a snapshot in particles.xdmf and a
# diagnostics row, and reports the liquid's bounds over the run. Label io.
add_test(NAME io_final_output COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/../io/final_output.sh ${DMHS_EXE}
         ${DMHS_PYTHON} ${CMAKE_BINARY_DIR}/test-output/io/final_output ${PROJECT_SOURCE_DIR}/input)
set_tests_properties(io_final_output PROPERTIES LABELS "io;validation" TIMEOUT 120)

# The same final output must not leak into a continued run: both halves end between output
# times (the first half's final snapshot and rows are replaced), against one run to the end,
# file by file (test/io/restart_scene.sh).
foreach(case "poiseuille_quick;0.015;-output_interval;0.01" "vein_quick;0.006;-output_interval;0.01")
  list(GET case 0 name)
  list(GET case 1 t_end)
  list(SUBLIST case 2 -1 extra)
  string(REPLACE "_" "-" input ${name})
  add_test(NAME io_restart_between_outputs_${name} COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/../io/restart_scene.sh
           ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_MPIRUN} -- ${CMAKE_BINARY_DIR}/test-output/restart/between_outputs_${name}
           2 2 1 ${t_end} -options_file ${PROJECT_SOURCE_DIR}/input/${input}.opts ${extra})
  set_tests_properties(io_restart_between_outputs_${name} PROPERTIES LABELS "io;mpi" PROCESSORS 2 TIMEOUT 180)
endforeach()

# -snapshot_every (test/io/snapshot_every.sh): snapshots at every Nth output time and at the
# last step, every diagnostics row kept, the cadence kept across a restart.
add_test(NAME io_snapshot_every COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/../io/snapshot_every.sh ${DMHS_EXE}
         ${DMHS_PYTHON} ${CMAKE_BINARY_DIR}/test-output/io/snapshot_every ${PROJECT_SOURCE_DIR}/input)
set_tests_properties(io_snapshot_every PROPERTIES LABELS "io;validation" TIMEOUT 180)
