# Deep-vein valve, quick variant (input/vein-quick.opts; doc/validation.md "Vein").
# On 2 ranks: the valve opens in forward flow and closes in backward flow, the
# leaflets never pass through each other, no liquid crosses a leaflet, the
# liquid stays weakly compressible, no NaN in any CSV; 1 rank gives the same
# CSVs byte for byte; a checkpoint at t = 0.3 s restarted on 1 rank too.
set(DMHS_VEIN ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/vein.py --exe ${DMHS_EXE}
    --opts ${PROJECT_SOURCE_DIR}/input/vein-quick.opts)
set(DMHS_VEIN_OUT ${CMAKE_CURRENT_BINARY_DIR}/vein)
string(REPLACE ";" " " DMHS_MPIRUN_STR "${DMHS_MPIRUN}")
# Multi-rank runs declare their processors, so ctest runs them alone; their
# timeouts allow for a machine shared with other jobs, where oversubscribed
# ranks that poll for messages run several times slower (about 50 s alone).
add_test(NAME validation_vein_quick_2ranks
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/quick-2ranks --ranks 2 --mpirun "${DMHS_MPIRUN_STR}")
set_tests_properties(validation_vein_quick_2ranks PROPERTIES LABELS "validation;mpi" TIMEOUT 900 PROCESSORS 2
                     FIXTURES_SETUP vein_quick_2ranks)
add_test(NAME validation_vein_quick COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/quick
                                            --compare ${DMHS_VEIN_OUT}/quick-2ranks)
set_tests_properties(validation_vein_quick PROPERTIES LABELS validation TIMEOUT 300
                     FIXTURES_SETUP vein_quick FIXTURES_REQUIRED vein_quick_2ranks)
add_test(NAME validation_vein_restart
         COMMAND ${DMHS_VEIN} --mode restart --outdir ${DMHS_VEIN_OUT}/restart --ranks 2 --restart-ranks 1
                 --mpirun "${DMHS_MPIRUN_STR}" --t-stop 0.3 --compare ${DMHS_VEIN_OUT}/quick-2ranks)
set_tests_properties(validation_vein_restart PROPERTIES LABELS "validation;io;mpi" TIMEOUT 900 PROCESSORS 2
                     FIXTURES_REQUIRED vein_quick_2ranks)
