# Peristaltic channel against Shapiro, Jaffrin & Weinberg's long-wavelength,
# low-Reynolds-number flux (doc/validation.md, "Peristaltic pumping"):
# input/peristaltic_channel-quick.opts (a/lambda = 0.025, Re = 0.1, 4 liquid
# particles across the half-width) over one wave period, at phi = b/a = 0.2,
# 0.5 and 0.8, one test each so that ctest -j2 runs them side by side. Each
# asserts the last period's |Q_mean/Q_theory - 1| <= 5 %, max |rho/rho0 - 1|
# <= 5 % and Mach <= 0.1 over the run, and fails on a missing, empty or
# malformed flux.csv or one with no completed period
# (test/validation/peristaltic.py). Measured: doc/validation.md.
set(DMHS_PERISTALTIC ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/peristaltic.py --exe ${DMHS_EXE})
set(DMHS_PERISTALTIC_QUICK ${PROJECT_SOURCE_DIR}/input/peristaltic_channel-quick.opts)
set(DMHS_PERISTALTIC_OUT ${CMAKE_BINARY_DIR}/test-output/validation/peristaltic)
string(REPLACE ";" " " DMHS_PERISTALTIC_MPIRUN "${DMHS_MPIRUN}")

set(DMHS_PERISTALTIC_DIRS)
foreach(case "phi02;0.2e-3" "phi05;0.5e-3" "phi08;0.8e-3")
  list(GET case 0 name)
  list(GET case 1 b)
  add_test(NAME validation_peristaltic_${name}
           COMMAND ${DMHS_PERISTALTIC} --opts ${DMHS_PERISTALTIC_QUICK} --outdir ${DMHS_PERISTALTIC_OUT}/${name}
                   --extra "-peristaltic_b ${b}")
  set_tests_properties(validation_peristaltic_${name} PROPERTIES LABELS validation TIMEOUT 600
                       FIXTURES_SETUP peristaltic_${name})
  list(APPEND DMHS_PERISTALTIC_DIRS ${DMHS_PERISTALTIC_OUT}/${name})
endforeach()

# The same case on 2 ranks: flux.csv byte for byte the 1-rank file.
add_test(NAME validation_peristaltic_phi02_2ranks
         COMMAND ${DMHS_PERISTALTIC} --opts ${DMHS_PERISTALTIC_QUICK} --outdir ${DMHS_PERISTALTIC_OUT}/phi02-2ranks
                 --extra "-peristaltic_b 0.2e-3" --ranks 2 --mpirun "${DMHS_PERISTALTIC_MPIRUN}"
                 --compare ${DMHS_PERISTALTIC_OUT}/phi02)
set_tests_properties(validation_peristaltic_phi02_2ranks PROPERTIES LABELS "validation;mpi" TIMEOUT 600
                     PROCESSORS 2 FIXTURES_REQUIRED peristaltic_phi02)

# The check itself refuses a missing, empty, misheaded, non-finite, short or
# inaccurate flux.csv and one without a completed period.
add_test(NAME validation_peristaltic_check_selftest COMMAND ${DMHS_PERISTALTIC} --selftest)
set_tests_properties(validation_peristaltic_check_selftest PROPERTIES LABELS validation TIMEOUT 60)

# A restart across a period's end: a short wave (lambda = 10 a, T = 10 s) to
# 15 s on 2 ranks against 2 ranks to 7.5 s + -restart on 1, every output
# compared (test/io/restart_scene.sh): flux.csv's row of the period that ends
# after the restart is the uninterrupted run's, so the running mean continued
# exactly.
add_test(NAME validation_peristaltic_restart
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/../io/restart_scene.sh ${DMHS_EXE} ${DMHS_PYTHON} ${DMHS_MPIRUN} --
                 ${DMHS_PERISTALTIC_OUT}/restart 2 2 1 15 -options_file ${DMHS_PERISTALTIC_QUICK}
                 -peristaltic_wavelength 0.01 -output_interval 2.5)
set_tests_properties(validation_peristaltic_restart PROPERTIES LABELS "validation;io;mpi" TIMEOUT 300
                     PROCESSORS 2)

# scripts/post/plot_peristaltic.py on the three quick runs: fails when an input
# is bad or the PNG is not written.
set(DMHS_PERISTALTIC_PNG ${DMHS_PERISTALTIC_OUT}/peristaltic_flux.png)
string(REPLACE ";" " " DMHS_PERISTALTIC_DIRS_STR "${DMHS_PERISTALTIC_DIRS}")
add_test(NAME validation_peristaltic_plot
         COMMAND sh -c "rm -f ${DMHS_PERISTALTIC_PNG} && ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/post/plot_peristaltic.py ${DMHS_PERISTALTIC_DIRS_STR} --out ${DMHS_PERISTALTIC_PNG} && test -s ${DMHS_PERISTALTIC_PNG}")
set_tests_properties(validation_peristaltic_plot PROPERTIES LABELS validation TIMEOUT 60
                     FIXTURES_REQUIRED "peristaltic_phi02;peristaltic_phi05;peristaltic_phi08")
# ... and refuses a directory without flux.csv.
add_test(NAME validation_peristaltic_plot_bad_input
         COMMAND ${DMHS_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/post/plot_peristaltic.py ${DMHS_PERISTALTIC_OUT}/no-such-run
                 --out ${DMHS_PERISTALTIC_OUT}/bad.png)
set_tests_properties(validation_peristaltic_plot_bad_input PROPERTIES LABELS validation TIMEOUT 60 WILL_FAIL TRUE)

# Twice the resolution over two periods (input/peristaltic_channel.opts; label full, about
# 10 min on one core): measured +0.33 % (doc/validation.md, "Peristaltic pumping").
add_test(NAME validation_peristaltic_fine
         COMMAND ${DMHS_PERISTALTIC} --opts ${PROJECT_SOURCE_DIR}/input/peristaltic_channel.opts
                 --outdir ${DMHS_PERISTALTIC_OUT}/fine)
set_tests_properties(validation_peristaltic_fine PROPERTIES LABELS "validation;full" TIMEOUT 3600)
