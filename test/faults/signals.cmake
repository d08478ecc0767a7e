# Stops that always checkpoint (label faults): a 2-rank run under mpirun gets
# SIGTERM or SIGINT as a process group, a double SIGTERM to one rank, SIGUSR1
# through mpirun; each must leave a checkpoint, run.json "signal-checkpoint",
# and continue from it to the outputs of an uninterrupted run, bitwise
# (test/faults/signal_stop.sh). A few seconds each.
foreach(case group_term group_int double_term usr1_mpirun)
  add_test(NAME faults_signal_${case} COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/signal_stop.sh ${DMHS_EXE}
           ${DMHS_PYTHON} ${CMAKE_BINARY_DIR}/test-output/faults/signal_${case} ${case} ${DMHS_MPIRUN})
  set_tests_properties(faults_signal_${case} PROPERTIES LABELS "faults;io;mpi" TIMEOUT 180 PROCESSORS 2)
endforeach()
