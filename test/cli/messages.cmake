# What a user reads when something is wrong (label cli; the helpers are cli.cmake's):
# an options file that includes another, run from elsewhere; "did you mean" for an
# option nobody read; one line per error, PETSc's trace only with -dmhs_traceback.

# -options_file X with -options_file Y inside, X given by an absolute path from a directory
# under /tmp: Y from X's directory upwards; one naming X and its line when Y is nowhere
# (test/cli/options_include.sh)
add_test(NAME cli_options_file_include COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/options_include.sh ${DMHS_EXE}
         ${DMHS_INPUT} ${DMHS_CLI_OUT}/options-include)
set_tests_properties(cli_options_file_include PROPERTIES LABELS cli TIMEOUT 60)

# the nearest options this run reads, by edit distance
dmhs_cli_fail(cli_did_you_mean "^dmhs: option -sph_hh 1 was not used .*\\(did you mean -sph_h\\?\\) .*dmhs: error: unknown or unused option -sph_hh \\(did you mean -sph_h\\?\\); run with -help"
  ${QUICK} -sph_hh 1 -output_dir ${DMHS_CLI_OUT}/did-you-mean)
dmhs_cli_fail(cli_did_you_mean_swap "option -t_ned 1 was not used .*\\(did you mean -t_end\\?\\).*option -output_dri x was not used .*\\(did you mean -output_dir\\?\\).* and 1 more; run with -help|option -output_dri x was not used .*\\(did you mean -output_dir\\?\\).*option -t_ned 1 was not used .*\\(did you mean -t_end\\?\\).* and 1 more; run with -help"
  ${QUICK} -t_ned 1 -output_dri x -output_dir ${DMHS_CLI_OUT}/did-you-mean)
dmhs_cli_fail(cli_did_you_mean_vein "unknown or unused option -vein_leaflet_k \\(did you mean -vein_leaflet_ka\\?\\)"
  -options_file ${DMHS_INPUT}/vein-quick.opts -vein_leaflet_k 0.01 -output_dir ${DMHS_CLI_OUT}/did-you-mean)
# nothing close: no guess
dmhs_cli_fail(cli_did_you_mean_none "unknown or unused option -zzzz; run with -help"
  ${QUICK} -zzzz 1 -output_dir ${DMHS_CLI_OUT}/did-you-mean)

# one line, without where in the source it was raised...
add_test(NAME cli_error_one_line COMMAND ${DMHS_EXPECT_FAIL} "^dmhs: error: -sph_h must be > 0 \\(got -1\\.\\) ?$" --lines 1 --
  ${DMHS_EXE} ${QUICK} -sph_h -1 -output_dir ${DMHS_CLI_OUT}/one-line)
set_tests_properties(cli_error_one_line PROPERTIES LABELS cli TIMEOUT 60)
add_test(NAME cli_error_one_line_options_file COMMAND ${DMHS_EXPECT_FAIL}
  "^dmhs: error: Unknown first token in options file .*bad-options.opts line 3: channel_nx ?$" --lines 1 --
  ${DMHS_EXE} -options_file ${CMAKE_CURRENT_LIST_DIR}/bad-options.opts)
set_tests_properties(cli_error_one_line_options_file PROPERTIES LABELS cli TIMEOUT 60)
# ... which -dmhs_traceback shows: PETSc's traceback, or before PETSc has read the options dmhs's
dmhs_cli_fail(cli_error_traceback "PETSC ERROR: -sph_h must be > 0 .*PETSC ERROR: #1 sph_set_from_options\\(\\) at .*sph\\.c:[0-9]+"
  ${QUICK} -sph_h -1 -dmhs_traceback -output_dir ${DMHS_CLI_OUT}/one-line)
dmhs_cli_fail(cli_error_traceback_options_file "^dmhs: error: Unknown first token .* dmhs:   \\(raised in PetscOptionsInsertFilePetsc\\(\\) at .*options\\.c:[0-9]+\\)"
  -options_file ${CMAKE_CURRENT_LIST_DIR}/bad-options.opts -dmhs_traceback)
