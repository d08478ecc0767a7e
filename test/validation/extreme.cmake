# Stiff and extreme cases (doc/stability.md): the flexible flap with very soft and very
# rigid leaflet angles, stiff bonds, the highest viscosity of the studies and a
# strong drive must run stably with the automatic time step (-dt 0) and keep
# the liquid out of the solid; a stiff bond at a fixed dt is refused before
# step 0; a nonlinear bond whose stiffness outgrows a fixed dt stops the run
# naming it, and with -dt 0 the run follows it to the end.
set(DMHS_EXT_OUT ${CMAKE_BINARY_DIR}/test-output/extreme)
# the plain step (no solid sub-steps): the limits of the flap's bonds and angles bind dt itself
set(EXT_FLAP -options_file ${PROJECT_SOURCE_DIR}/input/flap-quick.opts -solid_substeps 1 -quiet -checkpoint_at_end false
    -output_interval 0.005)

function(dmhs_extreme_ok name)
  add_test(NAME extreme_${name} COMMAND bash ${PROJECT_SOURCE_DIR}/test/cli/expect_ok.sh
    "fluid crossings 0.*dmhs summary" ${DMHS_EXT_OUT}/${name} --
    ${DMHS_EXE} ${EXT_FLAP} -dt 0 -output_dir ${DMHS_EXT_OUT}/${name} ${ARGN})
  set_tests_properties(extreme_${name} PROPERTIES LABELS validation TIMEOUT 120)
endfunction()

# The matrix (doc/stability.md): each case with -dt 0 runs to its end (no NaN
# in any output; the flap's and the vein's without a crossing), and at a fixed
# dt of 1.02 x its smallest limit stops before step 0 naming that limit. The
# automatic runs' figures go to test-output/extreme/matrix.csv.
set(DMHS_MATRIX_TABLE ${DMHS_EXT_OUT}/matrix.csv)
add_test(NAME extreme_matrix_reset COMMAND ${CMAKE_COMMAND} -E rm -f ${DMHS_MATRIX_TABLE})
set_tests_properties(extreme_matrix_reset PROPERTIES LABELS validation FIXTURES_SETUP extreme_matrix)
function(dmhs_matrix name expect)
  add_test(NAME extreme_${name} COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/stiff_matrix.py --exe ${DMHS_EXE}
    --outdir ${DMHS_EXT_OUT}/${name} --name ${name} --table ${DMHS_MATRIX_TABLE} --expect "${expect}" -- ${ARGN})
  set_tests_properties(extreme_${name} PROPERTIES LABELS validation TIMEOUT 300 FIXTURES_REQUIRED extreme_matrix
    RESOURCE_LOCK extreme_matrix_table)
endfunction()
set(EXT_CROSS "fluid crossings 0")
set(EXT_VEIN -options_file ${PROJECT_SOURCE_DIR}/input/vein-quick.opts -t_end 0.1 -checkpoint_at_end false)
set(EXT_COLON -options_file ${PROJECT_SOURCE_DIR}/input/intestine-quick.opts -t_end 0.1 -checkpoint_at_end false)
dmhs_matrix(soft_angles ${EXT_CROSS} ${EXT_FLAP} -angle_k 1e-4 -t_end 0.02)          # SPEC soft leaflets
dmhs_matrix(rigid_angles ${EXT_CROSS} ${EXT_FLAP} -angle_k 0.05 -t_end 0.002)        # SPEC most rigid
dmhs_matrix(stiff_bonds ${EXT_CROSS} ${EXT_FLAP} -bond_k 1e8 -t_end 0.001)           # 100x the leaflet K
dmhs_matrix(high_viscosity ${EXT_CROSS} ${EXT_FLAP} -sph_nu 5e-4 -t_end 0.02)        # the colon study's highest nu
dmhs_matrix(strong_drive ${EXT_CROSS} ${EXT_FLAP} -body_force_amplitude 5 -t_end 0.02) # 10x the drive
dmhs_matrix(vein_soft_leaflets "crossings 0" ${EXT_VEIN} -vein_leaflet_ka 1e-4)      # k_a 1e-4 J at dx = 1e-4
dmhs_matrix(vein_rigid_leaflets "crossings 0" ${EXT_VEIN} -vein_leaflet_ka 5e-2)     # k_a 5e-2 J
dmhs_matrix(vein_g0_04 "crossings 0" ${EXT_VEIN} -body_force_amplitude 0.4)          # the study's strongest g0
dmhs_matrix(colon_high_viscosity "dmhs summary" ${EXT_COLON} -sph_nu 5e-4)           # the colon study's highest nu
dmhs_matrix(colon_strong_drive "dmhs summary" ${EXT_COLON} -peristalsis_force 1)     # 3x the quick drive

add_test(NAME extreme_stiff_bonds_refused COMMAND ${DMHS_EXPECT_FAIL}
  "bond harmonic .*EXCEEDED.*pre-flight check failed" --
  ${DMHS_EXE} ${EXT_FLAP} -bond_k 1e8 -dt 1e-5 -t_end 0.001 -output_dir ${DMHS_EXT_OUT}/refused)
set_tests_properties(extreme_stiff_bonds_refused PROPERTIES LABELS validation TIMEOUT 60)

# The nonlinear bond near r_max: its stiffness grows with the stretch. At a
# fixed dt (0.8 x its limit at rest) the run stops when the stretch makes the
# limit fall below dt, naming it; with -dt 0 dt follows it down (1.7e-6 s from
# 7.2e-6 s, dt.csv) and the run reaches t_end.
set(EXT_NONLINEAR -bond_style nonlinear -bond_k 1e-6 -bond_rmax 2e-5 -body_force_amplitude 20 -t_end 0.05)
add_test(NAME extreme_nonlinear_bond_outgrows_dt COMMAND ${DMHS_EXPECT_FAIL}
  "dt = 7.155e-06 s exceeds the bond nonlinear limit .* at max stretch 0[.][0-9]+ r_max[)] that the state now sets"
  --no-nan ${DMHS_EXT_OUT}/nonlinear --
  ${DMHS_EXE} ${EXT_FLAP} -dt 7.155e-6 ${EXT_NONLINEAR} -output_dir ${DMHS_EXT_OUT}/nonlinear)
set_tests_properties(extreme_nonlinear_bond_outgrows_dt PROPERTIES LABELS validation TIMEOUT 60)
dmhs_extreme_ok(nonlinear_bond_adapts ${EXT_NONLINEAR})
# a fixture, not DEPENDS: DEPENDS only orders the tests, so the check read the dt.csv
# of an earlier run when this run failed or was not selected
set_tests_properties(extreme_nonlinear_bond_adapts PROPERTIES FIXTURES_SETUP extreme_nonlinear_bond_adapts)
add_test(NAME extreme_nonlinear_bond_adapts_dt_csv COMMAND ${DMHS_PYTHON}
  ${CMAKE_CURRENT_LIST_DIR}/dt_csv.py ${DMHS_EXT_OUT}/nonlinear_bond_adapts --min-changes 10 --limit "bond nonlinear")
set_tests_properties(extreme_nonlinear_bond_adapts_dt_csv PROPERTIES LABELS validation TIMEOUT 60
  FIXTURES_REQUIRED extreme_nonlinear_bond_adapts)
