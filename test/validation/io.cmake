# Output, checkpoints and restart (issue 5): scripts in test/io/, each a few
# seconds on one rank. Output under <build>/test-output/io/<test>.
set(DMHS_IO_OUT ${CMAKE_BINARY_DIR}/test-output/io)
set(DMHS_IO_DIR ${CMAKE_CURRENT_LIST_DIR}/../io)
foreach(t restart consistency signal corrupt)
  add_test(NAME io_${t} COMMAND bash ${DMHS_IO_DIR}/${t}.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_IO_OUT}/${t})
  set_tests_properties(io_${t} PROPERTIES LABELS "io;validation" TIMEOUT 180)
endforeach()
add_test(NAME io_signal_term COMMAND bash ${DMHS_IO_DIR}/signal.sh ${DMHS_EXE} ${DMHS_PYTHON}
  ${DMHS_IO_OUT}/signal_term TERM)
set_tests_properties(io_signal_term PROPERTIES LABELS "io;validation" TIMEOUT 180)
