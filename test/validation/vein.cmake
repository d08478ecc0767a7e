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
# Multi-rate contact (-repulsion_substeps with -solid_substeps 0, src/core/substep.c): the
# repulsion and the liquid in contact on the solids' sub-steps, so the sound speed binds dt
# (1.25e-5 s against the repulsion's 7.4e-6 s here). The leaflets' gap and tips within 2 % of
# their range of the plain step's over the opening (t <= 0.25 s; measured 1.7 %), the quick
# checks (density within 3 %: measured 2.2 %), 2 ranks byte for byte 1 rank's, a restart on
# another rank count exact. And the scheme: at the plain step's dt, the r-RESPA split of the
# liquid's forces keeps the density within 0.3 % (measured 0.11 %, plain 0.13 %), where holding
# them over the sub-steps (-solid_substeps_scheme held) let it reach 1.6 % and Mach 0.075.
set(DMHS_VEIN_MR "-solid_substeps 0 -repulsion_substeps -solid_substeps_scheme respa")
add_test(NAME validation_vein_contact_substeps
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/contact-substeps --extra "${DMHS_VEIN_MR}"
                 --near ${DMHS_VEIN_OUT}/quick-2ranks --near-tol 0.02)
set_tests_properties(validation_vein_contact_substeps PROPERTIES LABELS validation TIMEOUT 300
                     FIXTURES_SETUP vein_contact_substeps FIXTURES_REQUIRED vein_quick_2ranks)
add_test(NAME validation_vein_contact_substeps_2ranks
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/contact-substeps-2ranks --extra "${DMHS_VEIN_MR}"
                 --ranks 2 --mpirun "${DMHS_MPIRUN_STR}" --compare ${DMHS_VEIN_OUT}/contact-substeps)
set_tests_properties(validation_vein_contact_substeps_2ranks PROPERTIES LABELS "validation;mpi" TIMEOUT 900
                     PROCESSORS 2 FIXTURES_REQUIRED vein_contact_substeps)
add_test(NAME validation_vein_contact_substeps_restart
         COMMAND ${DMHS_VEIN} --mode restart --outdir ${DMHS_VEIN_OUT}/contact-substeps-restart --ranks 2
                 --restart-ranks 1 --mpirun "${DMHS_MPIRUN_STR}" --t-stop 0.3 --extra "${DMHS_VEIN_MR}"
                 --compare ${DMHS_VEIN_OUT}/contact-substeps)
set_tests_properties(validation_vein_contact_substeps_restart PROPERTIES LABELS "validation;io;mpi" TIMEOUT 900
                     PROCESSORS 2 FIXTURES_REQUIRED vein_contact_substeps)
# Stiff leaflets (k_a 50x the quick case's) with multi-rate contact and the automatic dt: the
# solids' fastest mode bounds dt (src/core/solid_modes.c). Without that limit the leaflets rang
# from t = 0.15 s (particles at 2.3 m/s); with the limit at a third of the fastest period they
# rang once the valve closed (2.2 m/s by t = 0.45 s); the plain step's leaflets stay below
# 0.01 m/s, and so do these (0.008 m/s). Stiff leaflets open less: 1.05 x the rest gap.
add_test(NAME validation_vein_stiff_substeps
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/stiff-substeps --open 1.05 --max-leaflet-speed 0.05
                 --extra "-vein_leaflet_ka 0.5 -output_interval 0.025 ${DMHS_VEIN_MR}")
set_tests_properties(validation_vein_stiff_substeps PROPERTIES LABELS validation TIMEOUT 600)
# The same stiff leaflets with dashpots on their bonds and angles (zeta 0.01) and the fastest-mode
# limit at 2.5/omega: dt 1.0e-5 s (the sound speed's at -dt_safety 0.65), 1.6x the limit's, a
# true omega dt of 1.3. Without the dashpots the leaflets ring there (1-4 m/s); with them they stay
# below 0.05 m/s. These leaflets barely move (the tips over 0.3 dx), and how they move depends on
# the step: the undamped run at half its dt (-dt_safety 0.4) departs from it by 0.19-0.22 of the
# gap's and tips' range. The damped run must be closer than that to the half-dt run (0.13-0.15).
add_test(NAME validation_vein_stiff_fine
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/stiff-fine --open 1.05 --max-leaflet-speed 0.05
                 --extra "-vein_leaflet_ka 0.5 -output_interval 0.025 ${DMHS_VEIN_MR} -dt_safety 0.4")
set_tests_properties(validation_vein_stiff_fine PROPERTIES LABELS validation TIMEOUT 900
                     FIXTURES_SETUP vein_stiff_fine)
add_test(NAME validation_vein_stiff_damped
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/stiff-damped --open 1.05 --max-leaflet-speed 0.05
                 --near ${DMHS_VEIN_OUT}/stiff-fine --near-tol 0.18 --near-t-max 0.5
                 --extra "-vein_leaflet_ka 0.5 -output_interval 0.025 ${DMHS_VEIN_MR} -bond_damping 0.01 -angle_damping 0.01 -solid_mode_dt_factor 2.5 -dt_safety 0.65")
set_tests_properties(validation_vein_stiff_damped PROPERTIES LABELS validation TIMEOUT 600
                     FIXTURES_REQUIRED vein_stiff_fine)
add_test(NAME validation_vein_contact_substeps_respa
         COMMAND ${DMHS_VEIN} --outdir ${DMHS_VEIN_OUT}/contact-substeps-respa --max-rho-dev 0.003
                 --extra "-dt 7e-6 -solid_substeps 2 -repulsion_substeps -solid_substeps_scheme respa")
set_tests_properties(validation_vein_contact_substeps_respa PROPERTIES LABELS validation TIMEOUT 300)
