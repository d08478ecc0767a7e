# Intestine with peristalsis (SPEC 4.2), quick variant input/intestine-quick.opts
# (3 pockets, dx = 5e-4 m, 0.26 s, ~3 s on one core; doc/validation.md
# "Intestine"). Measured: segments at the end of their +1 / -1 sub-periods
# +2.7e-3 / -2.5e-3 m from rest (asserted: > 5e-4 m in the right direction),
# x_F +2.6e-3 m while pocket 0 squeezes (asserted > 5e-4 m), fluid + overflow
# conserved in every row, no NaN; 2 ranks give a bitwise identical CSV.
set(DMHS_INTESTINE ${DMHS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/validation/intestine.py --exe ${DMHS_EXE}
    --opts ${PROJECT_SOURCE_DIR}/input/intestine-quick.opts)
set(DMHS_INTESTINE_OUT ${CMAKE_CURRENT_BINARY_DIR}/intestine)
add_test(NAME validation_intestine_quick COMMAND ${DMHS_INTESTINE} --outdir ${DMHS_INTESTINE_OUT}/quick)
set_tests_properties(validation_intestine_quick PROPERTIES LABELS validation TIMEOUT 120
                     FIXTURES_SETUP intestine_quick)
string(REPLACE ";" " " DMHS_MPIRUN_STR "${DMHS_MPIRUN}")
add_test(NAME validation_intestine_quick_2ranks
         COMMAND ${DMHS_INTESTINE} --outdir ${DMHS_INTESTINE_OUT}/quick-2ranks --ranks 2 --mpirun "${DMHS_MPIRUN_STR}"
                 --compare ${DMHS_INTESTINE_OUT}/quick)
set_tests_properties(validation_intestine_quick_2ranks PROPERTIES LABELS "validation;mpi" TIMEOUT 120 PROCESSORS 2
                     FIXTURES_REQUIRED intestine_quick)
# A weir below the level (2.5 mm < L = 4.6 mm): liquid overflows from the
# start and is parked; fluid + overflow conserved. The falling liquid comes
# closer to the membrane than at the quick input's fixed dt = 3e-5 s the
# repulsion allows (its limit falls to 2.9e-5 s at t = 0.23 s and the run
# stops, naming it): the automatic dt follows it.
add_test(NAME validation_intestine_overflow
         COMMAND ${DMHS_INTESTINE} --outdir ${DMHS_INTESTINE_OUT}/overflow --extra "-intestine_weir 0.0025 -dt 0"
                 --min-overflow 10)
set_tests_properties(validation_intestine_overflow PROPERTIES LABELS validation TIMEOUT 120)
# -peristalsis_schedule: a custom matrix is followed (pocket 2 +1 rises,
# pocket 0 -1 sinks); a value 2 and a short row are errors naming file:line.
add_test(NAME validation_intestine_schedule COMMAND ${DMHS_INTESTINE} --mode schedule --outdir ${DMHS_INTESTINE_OUT}/schedule)
set_tests_properties(validation_intestine_schedule PROPERTIES LABELS validation TIMEOUT 120)
# Checkpoint at t = 0.13 s and -restart: intestine.csv (x_F history, counts,
# lifts) identical to the uninterrupted quick run.
add_test(NAME validation_intestine_restart
         COMMAND ${DMHS_INTESTINE} --mode restart --outdir ${DMHS_INTESTINE_OUT}/restart --compare ${DMHS_INTESTINE_OUT}/quick)
set_tests_properties(validation_intestine_restart PROPERTIES LABELS "validation;io" TIMEOUT 120
                     FIXTURES_REQUIRED intestine_quick)
