# The LAMMPS twins' helpers that need no LAMMPS. Label: validation.
# bench/lammps/vein_data.py: a coarse vein's t = 0 state as the twin's data and parameter
# files, checked particle by particle, bond by bond and angle by angle (lammps_vein_data.sh)
add_test(NAME validation_lammps_vein_data
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/lammps_vein_data.sh ${DMHS_EXE} ${DMHS_PYTHON}
                 ${CMAKE_BINARY_DIR}/test-output/lammps-vein-data)
set_tests_properties(validation_lammps_vein_data PROPERTIES LABELS validation TIMEOUT 120)
