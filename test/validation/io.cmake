# Output, checkpoints and restart: scripts in test/io/, each a few
# seconds on one rank. Output under <build>/test-output/io/<test>.
set(DMHS_IO_OUT ${CMAKE_BINARY_DIR}/test-output/io)
set(DMHS_IO_DIR ${CMAKE_CURRENT_LIST_DIR}/../io)
foreach(t restart consistency signal corrupt restart_options outdir console_log)
  add_test(NAME io_${t} COMMAND bash ${DMHS_IO_DIR}/${t}.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_IO_OUT}/${t})
  set_tests_properties(io_${t} PROPERTIES LABELS "io;validation" TIMEOUT 180)
endforeach()
add_test(NAME io_signal_term COMMAND bash ${DMHS_IO_DIR}/signal.sh ${DMHS_EXE} ${DMHS_PYTHON}
  ${DMHS_IO_OUT}/signal_term TERM)
set_tests_properties(io_signal_term PROPERTIES LABELS "io;validation" TIMEOUT 180)

# the parallel row layout on 3 ranks with uneven and empty row counts (h5io_mpi.sh)
add_executable(h5io_mpi ${DMHS_IO_DIR}/h5io_mpi.c)
target_include_directories(h5io_mpi PRIVATE ${PROJECT_SOURCE_DIR}/src)
target_compile_options(h5io_mpi PRIVATE ${DMHS_WARNINGS})
target_link_libraries(h5io_mpi PRIVATE dmhs_core)
add_test(NAME io_h5io_mpi COMMAND bash ${DMHS_IO_DIR}/h5io_mpi.sh $<TARGET_FILE:h5io_mpi> ${DMHS_PYTHON}
  ${DMHS_IO_OUT}/h5io_mpi ${DMHS_MPIRUN})
set_tests_properties(io_h5io_mpi PROPERTIES LABELS "io;mpi" TIMEOUT 120)

# Bonds drawn as an XDMF Polyline over the snapshot's particles, on 2 ranks.
add_test(NAME io_bonds COMMAND bash ${DMHS_IO_DIR}/bonds.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_MPIRUN} -- ${DMHS_IO_OUT}/bonds)
set_tests_properties(io_bonds PROPERTIES LABELS "io;mpi" TIMEOUT 120)

# Restart on another rank count (2 -> 3, 2 -> 1): bitwise the same as one rank throughout.
add_test(NAME io_restart_ranks COMMAND bash ${DMHS_IO_DIR}/restart_ranks.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_MPIRUN}
  -- ${DMHS_IO_OUT}/restart_ranks)
set_tests_properties(io_restart_ranks PROPERTIES LABELS "io;mpi" TIMEOUT 120)

# The progress lines (one after every step, rank 0's clock deciding) change no output, on 2 ranks.
add_test(NAME io_progress_bitwise COMMAND bash ${DMHS_IO_DIR}/progress_bitwise.sh ${DMHS_EXE} ${DMHS_PYTHON}
  ${DMHS_MPIRUN} -- ${DMHS_IO_OUT}/progress_bitwise)
set_tests_properties(io_progress_bitwise PROPERTIES LABELS "io;mpi" PROCESSORS 2 TIMEOUT 180)

# Fault injection (label faults): a full disk (a small tmpfs; skipped without root/mount), and
# test/io/faults.py: SIGTERM / SIGKILL while a checkpoint or a snapshot is being written, a
# temporary name taken by a directory, a truncated and a bit-flipped checkpoint. Each must leave
# a checkpoint that restarts, no .tmp once the directory is used again, and a run.json that says
# what happened.
add_test(NAME faults_disk_full COMMAND bash ${DMHS_IO_DIR}/diskfull.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_IO_OUT}/diskfull)
set_tests_properties(faults_disk_full PROPERTIES LABELS "faults;io" TIMEOUT 120 SKIP_RETURN_CODE 77)
foreach(case term_checkpoint kill_checkpoint term_snapshot kill_snapshot blocked_snapshot blocked_checkpoint
        truncated flipped)
  add_test(NAME faults_${case} COMMAND ${DMHS_PYTHON} ${DMHS_IO_DIR}/faults.py ${DMHS_EXE} ${DMHS_IO_OUT}/faults_${case}
           ${case})
  set_tests_properties(faults_${case} PROPERTIES LABELS "faults;io" TIMEOUT 180)
endforeach()
