# What a user types: -help, bad options and values, pre-flight refusals, a
# blow-up that must stop cleanly, -log_view. Label: cli.
set(DMHS_INPUT ${PROJECT_SOURCE_DIR}/input)
set(DMHS_EXPECT_FAIL bash ${CMAKE_CURRENT_LIST_DIR}/expect_fail.sh)
# exit status 0 and the output matching a regex (PASS_REGULAR_EXPRESSION would ignore the status)
set(DMHS_EXPECT_OUTPUT bash ${CMAKE_CURRENT_LIST_DIR}/expect_output.sh)
set(DMHS_CLI_OUT ${CMAKE_BINARY_DIR}/test-output/cli)
set(QUICK -options_file ${DMHS_INPUT}/poiseuille-quick.opts -quiet)

add_test(NAME cli_help COMMAND ${DMHS_EXPECT_OUTPUT}
  "-scene <poiseuille>.*-neighbour_skin <.*-sph_h <.*support radius h \\[m\\].*-body_force <.*\\[m/s\\^2\\].*Scene couette.*-wall_speed <.*Scene box.*-box_nx.*-angle_k <.*-repulsion_rstar <.*-bond_rmax <"
  -- ${DMHS_EXE} -help)
set_tests_properties(cli_help PROPERTIES LABELS cli TIMEOUT 60)
# each option once, with the chosen scene's values (test/cli/help.sh)
add_test(NAME cli_help_scene_values COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/help.sh ${DMHS_EXE} ${DMHS_INPUT})
set_tests_properties(cli_help_scene_values PROPERTIES LABELS cli TIMEOUT 60)

function(dmhs_cli_fail name regex)
  add_test(NAME ${name} COMMAND ${DMHS_EXPECT_FAIL} "${regex}" -- ${DMHS_EXE} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS cli TIMEOUT 60)
endfunction()

dmhs_cli_fail(cli_unknown_option "unknown or unused option -sph_hh" ${QUICK} -sph_hh 1 -output_dir ${DMHS_CLI_OUT}/a)
# a module the scene does not enable must not silently swallow its options
dmhs_cli_fail(cli_option_not_in_scene "unknown or unused option -body_force"
  -options_file ${DMHS_INPUT}/couette-quick.opts -body_force 1,0 -output_dir ${DMHS_CLI_OUT}/b)
# a word that is neither an option nor its value (PETSc would drop it silently)
dmhs_cli_fail(cli_stray_argument "stray argument '1e-6' \\(word 6 of the command line\\)" ${QUICK} -sph_nu 1e-5 1e-6
  -output_dir ${DMHS_CLI_OUT}/stray)
dmhs_cli_fail(cli_unknown_scene "-scene intestin: unknown scene" ${QUICK} -scene intestin)
dmhs_cli_fail(cli_bad_value "-sph_h must be > 0" ${QUICK} -sph_h -1 -output_dir ${DMHS_CLI_OUT}/c)
dmhs_cli_fail(cli_bad_enum "sph_kernel" ${QUICK} -sph_kernel gauss -output_dir ${DMHS_CLI_OUT}/d)
dmhs_cli_fail(cli_non_square_lattice "lattice must be square" ${QUICK} -channel_nx 30 -output_dir ${DMHS_CLI_OUT}/e)
dmhs_cli_fail(cli_unwritable_output_dir "-output_dir /proc/dmhs" ${QUICK} -output_dir /proc/dmhs/out)
# errors while PETSc reads the options files are one line too (the handler is in place before PetscInitialize)
add_test(NAME cli_missing_options_file COMMAND ${DMHS_EXPECT_FAIL}
  "^dmhs: error: Unable to open options file .*no-such-case.opts" --lines 2 --
  ${DMHS_EXE} -options_file ${DMHS_INPUT}/no-such-case.opts)
set_tests_properties(cli_missing_options_file PROPERTIES LABELS cli TIMEOUT 60)
# Values validated where they are read (include/dmhs/options.h): one line naming the option, the
# value and what it takes
add_test(NAME cli_bad_options_file COMMAND ${DMHS_EXPECT_FAIL}
  "^dmhs: error: Unknown first token in options file .*bad-options.opts line 3: channel_nx" --lines 2 --
  ${DMHS_EXE} -options_file ${CMAKE_CURRENT_LIST_DIR}/bad-options.opts)
set_tests_properties(cli_bad_options_file PROPERTIES LABELS cli TIMEOUT 60)
foreach(case "t_end;inf" "dt;inf" "sph_c0;inf" "sph_nu;nan" "sph_h;-inf" "gravity;1e999")
  list(GET case 0 opt)
  list(GET case 1 value)
  dmhs_cli_fail(cli_nonfinite_${opt} "-${opt} ${value}: not finite; -${opt} takes a finite real number"
    ${QUICK} -${opt} ${value} -output_dir ${DMHS_CLI_OUT}/nonfinite)
endforeach()
dmhs_cli_fail(cli_body_force_components "-body_force 1e-4,0,0: 3 values, but -body_force takes up to 2"
  ${QUICK} -body_force 1e-4,0,0 -output_dir ${DMHS_CLI_OUT}/k)
dmhs_cli_fail(cli_array_element "-body_force 1e-4,x: 'x' is not a number" ${QUICK} -body_force 1e-4,x
  -output_dir ${DMHS_CLI_OUT}/k)
dmhs_cli_fail(cli_garbage_real "-dt garbage: not a number; -dt takes a finite real number"
  ${QUICK} -dt garbage -output_dir ${DMHS_CLI_OUT}/k)
dmhs_cli_fail(cli_garbage_int "-channel_nx 2.5: not an integer" ${QUICK} -channel_nx 2.5 -output_dir ${DMHS_CLI_OUT}/k)
dmhs_cli_fail(cli_garbage_bool "-quiet maybe: not a boolean" ${QUICK} -quiet maybe -output_dir ${DMHS_CLI_OUT}/k)
# an option last on the line without its value (-dt alone used to mean -dt 0, automatic)
dmhs_cli_fail(cli_missing_value "option -dt was given without a value; it takes a finite real number"
  ${QUICK} -output_dir ${DMHS_CLI_OUT}/k -dt)
dmhs_cli_fail(cli_missing_string "option -output_dir was given without a value" ${QUICK} -output_dir)
# the quadratic wall extrapolation needs the wall geometry, which only the channel scenes give
dmhs_cli_fail(cli_wall_quadratic_without_geometry
  "-sph_wall_extrapolation quadratic needs each wall particle's vector to the wall surface, which scene flap"
  -options_file ${DMHS_INPUT}/flap-quick.opts -sph_wall_extrapolation quadratic -t_end 1e-4
  -output_dir ${DMHS_CLI_OUT}/wall_quadratic)
# the published dt = 1e-4 s exceeds the viscous limit at 40 x 80: refused before step 0
dmhs_cli_fail(cli_preflight_published_dt "viscosity .*EXCEEDED.*pre-flight check failed"
  -options_file ${DMHS_INPUT}/poiseuille.opts -dt 1e-4 -output_dir ${DMHS_CLI_OUT}/f)
# the published intestine ratio h = dx leaves no neighbour inside the support
dmhs_cli_fail(cli_preflight_h_equals_dx "0 neighbours inside the support.*TOO FEW"
  ${QUICK} -sph_h 2.5e-5 -dt 1e-5 -output_dir ${DMHS_CLI_OUT}/g)
# forced past the limits, the run must stop with step, time, particle and field, and no NaN written
add_test(NAME cli_blowup_stops_cleanly COMMAND ${DMHS_EXPECT_FAIL}
  "run blew up at step [0-9]+, t = .* particle gid [0-9]+ .*(density|velocity|position|pressure)|escaped the domain"
  --no-nan ${DMHS_CLI_OUT}/blowup --
  ${DMHS_EXE} ${QUICK} -dt 2e-3 -preflight warn -t_end 0.5 -output_interval 0.002 -output_dir ${DMHS_CLI_OUT}/blowup)
set_tests_properties(cli_blowup_stops_cleanly PROPERTIES LABELS cli TIMEOUT 60)
# finite positions and velocities but a non-finite acceleration at t = 0 (gravity 1e300 overflows the
# wall pressure): stopped before snap_000000.h5, naming step, particle and field
add_test(NAME cli_nonfinite_acceleration_stops COMMAND ${DMHS_EXPECT_FAIL}
  "run blew up at step 0, t = 0.* particle gid [0-9]+ .*non-finite or invalid acceleration"
  --no-nan ${DMHS_CLI_OUT}/gravity --
  ${DMHS_EXE} ${QUICK} -gravity 1e300 -preflight warn -t_end 0.01 -output_dir ${DMHS_CLI_OUT}/gravity)
set_tests_properties(cli_nonfinite_acceleration_stops PROPERTIES LABELS cli TIMEOUT 60)

add_test(NAME cli_log_view COMMAND ${DMHS_EXPECT_OUTPUT} "SphForce.*SphWall.*BodyForce|SphWall.*SphForce" --
  ${DMHS_EXE} ${QUICK} -t_end 0.01 -log_view -output_dir ${DMHS_CLI_OUT}/h)
set_tests_properties(cli_log_view PROPERTIES LABELS cli TIMEOUT 60)
add_test(NAME cli_summary_line COMMAND ${DMHS_EXPECT_OUTPUT}
  "step +[0-9]+ +t .*particle-steps/s .*ETA.*max\\|v\\|.*dmhs summary: .*particle-steps/s: [0-9.e+]+" --
  ${DMHS_EXE} -options_file ${DMHS_INPUT}/poiseuille-quick.opts -t_end 0.01 -output_dir ${DMHS_CLI_OUT}/i)
set_tests_properties(cli_summary_line PROPERTIES LABELS cli TIMEOUT 60)
dmhs_cli_fail(cli_bad_body_force_type "-body_force_types: 'wall' is not fluid or solid"
  -options_file ${DMHS_INPUT}/flap-quick.opts -quiet -body_force_types fluid,wall -output_dir ${DMHS_CLI_OUT}/j)
add_test(NAME cli_slurm_script COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/slurm.sh ${PROJECT_SOURCE_DIR} ${DMHS_EXE}
  ${DMHS_CLI_OUT}/slurm)
set_tests_properties(cli_slurm_script PROPERTIES LABELS cli TIMEOUT 60)
# a pulsatile poiseuille run needs a drive along x to compare with the Womersley series
dmhs_cli_fail(cli_pulsatile_without_drive "-body_force_period 0.206 s the drive along x is 0: set -body_force_amplitude"
  -options_file ${DMHS_INPUT}/womersley-quick.opts -quiet -body_force_amplitude 0 -output_dir ${DMHS_CLI_OUT}/k)
# scripts/slurm/vein-study.sbatch: an array task runs its study run, skips it when completed, continues it after a signal
add_test(NAME cli_vein_study_script COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/vein_study.sh ${PROJECT_SOURCE_DIR} ${DMHS_EXE}
  ${DMHS_CLI_OUT}/vein-study)
set_tests_properties(cli_vein_study_script PROPERTIES LABELS cli TIMEOUT 120)
# scripts/slurm/colon-study.sbatch in its dry-run mode: task id -> (L, nu, V_w) and t_w, the grid's corners,
# ids out of range refused, a completed run skipped, a checkpointed one continued (test/cli/colon_study.sh)
add_test(NAME cli_colon_study_script COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/colon_study.sh ${PROJECT_SOURCE_DIR}
  ${DMHS_CLI_OUT}/colon-study)
set_tests_properties(cli_colon_study_script PROPERTIES LABELS cli TIMEOUT 60)
# every scripts/slurm/*.sbatch with --dry-run outside Slurm: the srun command (and with RESUBMIT=1 the
# sbatch) it would run, nothing run, a restart and a skip, bad task ids and a missing options file
# refused; the site placeholders (account, partition, modules) and how to change tasks and time
# (test/cli/slurm_dry_run.sh)
add_test(NAME cli_slurm_dry_run COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/slurm_dry_run.sh ${PROJECT_SOURCE_DIR}
  ${DMHS_CLI_OUT}/slurm-dry-run)
set_tests_properties(cli_slurm_dry_run PROPERTIES LABELS cli TIMEOUT 60)
# the colon study's inputs parse (read from the repository root, as they read input/intestine.opts) and
# -help shows their overrides
foreach(case "L081|-output_dir <output/intestine-L081>.*-intestine_level <0.0081>"
             "L111|-output_dir <output/intestine-L111>.*-intestine_level <0.0111>"
             "L157|-output_dir <output/intestine-L157>.*-intestine_level <0.0157>"
             "new-wave|-output_dir <output/intestine-new-wave>.*-intestine_level <0.0046>.*-intestine_red <true>.*-intestine_red_pocket <4>.*-peristalsis_h <5>"
             "old-wave-red|-output_dir <output/intestine-old-wave-red>.*-intestine_level <0.0046>.*-intestine_red <true>.*-intestine_red_pocket <4>.*-peristalsis_h <2>"
             "fast-wave|-output_dir <output/intestine-fast-wave>.*-sph_c0 <15>.*-sph_av_alpha <0.1>.*-peristalsis_tw <0.0334448>"
             "L046-nu2e-6|-output_dir <output/intestine-L046-nu2e-6>.*-intestine_level <0.0046>.*-sph_nu <2e-06>.*-peristalsis_tw <0.6>.*-peristalsis_h <2>"
             "L081-nu1.6e-6|-output_dir <output/intestine-L081-nu1.6e-6>.*-intestine_level <0.0081>.*-sph_nu <1.6e-06>.*-peristalsis_tw <0.6>.*-peristalsis_h <2>"
             "L111-old-wave|-output_dir <output/intestine-L111-old-wave>.*-intestine_level <0.0111>.*-intestine_red <true>.*-intestine_red_pocket <4>.*-sph_nu <1e-06>.*-peristalsis_tw <0.6>.*-peristalsis_h <2>"
             "L111-new-wave|-output_dir <output/intestine-L111-new-wave>.*-intestine_level <0.0111>.*-intestine_red <true>.*-intestine_red_pocket <4>.*-sph_nu <1e-06>.*-peristalsis_tw <0.6>.*-peristalsis_h <5>")
  string(FIND "${case}" "|" bar)
  string(SUBSTRING "${case}" 0 ${bar} name)
  math(EXPR bar "${bar} + 1")
  string(SUBSTRING "${case}" ${bar} -1 regex)
  add_test(NAME cli_colon_study_input_${name} COMMAND ${DMHS_EXPECT_OUTPUT} "${regex}"
    -- ${DMHS_EXE} -options_file input/intestine-${name}.opts -help)
  set_tests_properties(cli_colon_study_input_${name} PROPERTIES LABELS cli TIMEOUT 60
                       WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endforeach()
# the inputs of the thesis's colon figures start: each reads input/intestine.opts (from the
# repository root), builds its case and runs 4 steps (~2-5 s). Checked in the run's output: the
# liquid (the level), nu, the wave's H and T_w, and the CSV header's tracked sets (its first
# line, printed after the run); a red set in pocket 4 has columns red_0 .. red_10.
foreach(case "L081|particles: 29580 fluid.*nu = 1e-06 m\\^2/s.*T_w = 13.8 s, H = 2\\).*level 0.0081 m.*white_10,alpha,overflow"
             "L046-nu2e-6|particles: 18380 fluid.*nu = 2e-06 m\\^2/s.*T_w = 13.8 s, H = 2\\).*level 0.0046 m.*white_10,alpha,overflow"
             "L081-nu1.6e-6|particles: 29580 fluid.*nu = 1.6e-06 m\\^2/s.*T_w = 13.8 s, H = 2\\).*level 0.0081 m.*white_10,alpha,overflow"
             "L111-old-wave|particles: 39180 fluid.*nu = 1e-06 m\\^2/s.*T_w = 13.8 s, H = 2\\).*level 0.0111 m.*alpha,red_0,.*red_4,.*red_10,overflow"
             "L111-new-wave|particles: 39180 fluid.*nu = 1e-06 m\\^2/s.*T_w = 13.8 s, H = 5\\).*level 0.0111 m.*alpha,red_0,.*red_4,.*red_10,overflow")
  string(FIND "${case}" "|" bar)
  string(SUBSTRING "${case}" 0 ${bar} name)
  math(EXPR bar "${bar} + 1")
  string(SUBSTRING "${case}" ${bar} -1 regex)
  set(dir ${DMHS_CLI_OUT}/colon-input-${name})
  add_test(NAME cli_colon_input_starts_${name} COMMAND ${DMHS_EXPECT_OUTPUT} "${regex}"
    -- sh -c "rm -rf ${dir} && \"$0\" -options_file input/intestine-${name}.opts -t_end 2.5e-5 -output_snapshots false -checkpoint_at_end false -output_dir ${dir} && head -n 2 ${dir}/intestine.csv"
    ${DMHS_EXE})
  set_tests_properties(cli_colon_input_starts_${name} PROPERTIES LABELS cli TIMEOUT 120
                       WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endforeach()
# scripts/post/plot_intestine_study.py on synthetic summaries: Re, Re_P, a run with alpha_T n/a skipped,
# a malformed or missing summary refused (test/cli/colon_study_plot.py)
add_test(NAME cli_colon_study_plot COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/colon_study_plot.py
  ${PROJECT_SOURCE_DIR}/scripts/post/plot_intestine_study.py ${DMHS_CLI_OUT}/colon-study-plot)
set_tests_properties(cli_colon_study_plot PROPERTIES LABELS cli TIMEOUT 60)
# scripts/post/sph_grid.py, the kernel interpolation behind plot_fields.py and the vein's maps, on
# synthetic lattices: the kernels' normalisation, periodic boxes (sums across the boundary, periods
# of 2 and 3 cells), a free edge (test/cli/sph_grid_selftest.py)
add_test(NAME cli_sph_grid_selftest COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/sph_grid_selftest.py
  ${PROJECT_SOURCE_DIR}/scripts/post)
set_tests_properties(cli_sph_grid_selftest PROPERTIES LABELS cli TIMEOUT 60)
# scripts/post/particle_spacing.py: the paired-up liquid particles of a made-up snapshot, one pair
# across the periodic boundary, a wall particle left out; bad --below values and no snapshot fail
add_test(NAME cli_particle_spacing COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/particle_spacing_check.py
  ${PROJECT_SOURCE_DIR}/scripts/post ${DMHS_CLI_OUT}/particle-spacing)
set_tests_properties(cli_particle_spacing PROPERTIES LABELS cli TIMEOUT 60)
# progress lines at the simulated and the wall-clock interval, the projection after 100 steps
# (the step count of the automatic dt as taken), -quiet (test/cli/progress.sh)
add_test(NAME cli_progress_lines COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/progress.sh ${DMHS_EXE} ${DMHS_INPUT}
  ${DMHS_CLI_OUT}/progress)
set_tests_properties(cli_progress_lines PROPERTIES LABELS cli TIMEOUT 120)
add_test(NAME cli_help_progress_wall_interval COMMAND ${DMHS_EXPECT_OUTPUT}
  "-progress_wall_interval <600> +Wall-clock time .*\\[s\\]" -- ${DMHS_EXE} -help)
set_tests_properties(cli_help_progress_wall_interval PROPERTIES LABELS cli TIMEOUT 60)
dmhs_cli_fail(cli_bad_progress_wall_interval "-progress_wall_interval must be >= 0 s \\(got -1"
  ${QUICK} -progress_wall_interval -1 -output_dir ${DMHS_CLI_OUT}/progress-bad)
# run.json's commit, host, pid and heartbeat; scripts/run_state.sh tells running, stalled and died
# apart, and scripts/vein_study.sh leaves a running run alone (test/cli/run_state.sh)
add_test(NAME cli_run_state COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_state.sh ${PROJECT_SOURCE_DIR} ${DMHS_EXE}
  ${DMHS_PYTHON} ${DMHS_CLI_OUT}/run-state)
set_tests_properties(cli_run_state PROPERTIES LABELS cli TIMEOUT 120)
# the last step may pass t_end by dt/2: the progress line then says ETA 0.0 s, never -0.0 s
add_test(NAME cli_eta_not_negative COMMAND ${DMHS_EXPECT_OUTPUT} "step +337 .* ETA +0.0 s" --reject "ETA +-" --
  ${DMHS_EXE} -options_file ${DMHS_INPUT}/poiseuille-quick.opts -dt 3e-5
  -t_end 0.0101 -output_snapshots false -output_dir ${DMHS_CLI_OUT}/eta)
set_tests_properties(cli_eta_not_negative PROPERTIES LABELS cli TIMEOUT 60)
# out of memory (a 1 GB address-space limit, 4e8 particles): says what and how much
add_test(NAME cli_out_of_memory COMMAND ${DMHS_EXPECT_FAIL}
  "out of memory: cannot allocate 3200 MB for particle field 'gid' \\(room for 400000000 particles.*124 bytes per particle"
  -- bash -c "ulimit -v 1000000 && exec \"$0\" \"$@\"" ${DMHS_EXE} -scene box -box_nx 20000 -box_ny 20000
  -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/oom)
set_tests_properties(cli_out_of_memory PROPERTIES LABELS cli TIMEOUT 60)
# run.json's "halo" (halo sizes over the ranks at the last build): every count an integer, the
# owned rows summing to the particles, the one-rank ghosts equal to the lattice's periodic images
add_test(NAME cli_run_json_halo COMMAND ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/run_json_halo.py
  ${DMHS_CLI_OUT}/run_json_halo ${DMHS_MPIRUN} -- ${DMHS_EXE})
set_tests_properties(cli_run_json_halo PROPERTIES LABELS "cli;mpi" PROCESSORS 2 TIMEOUT 120)
# a scene without walls has no v_visc field: every SPH sweep (corrected, pair list) reads v_est
add_test(NAME cli_box_without_v_visc COMMAND ${DMHS_EXPECT_OUTPUT}
  "dmhs summary: scene box, 400 particles.*20 steps"
  -- ${DMHS_EXE} -scene box -box_nx 20 -box_ny 20 -dt 1e-6 -t_end 2e-5 -sph_kernel_correction true
  -sph_force_sweep pairs -quiet -output_dir ${DMHS_CLI_OUT}/box_no_v_visc)
set_tests_properties(cli_box_without_v_visc PROPERTIES LABELS cli TIMEOUT 60)
# a wave too fast for the sound speed is named before the run (the membrane's peak speed against
# -sph_c0), and the quick colon's own wave is not
add_test(NAME cli_intestine_fast_wave_warning COMMAND ${DMHS_EXPECT_OUTPUT}
  "membrane speed +U_m = 1.5 \\(F/k_s\\)/\\(ramp t_w\\) = 1.5 m/s.*LOW.*WARNING: -sph_c0 5 m/s is below 30 U_m = 45 m/s"
  -- ${DMHS_EXE} -options_file ${DMHS_INPUT}/intestine-quick.opts -peristalsis_tw 0.006 -t_end 1e-5
  -output_snapshots false -output_dir ${DMHS_CLI_OUT}/fast-wave)
set_tests_properties(cli_intestine_fast_wave_warning PROPERTIES LABELS cli TIMEOUT 60)
add_test(NAME cli_intestine_wave_speed_ok COMMAND ${DMHS_EXPECT_OUTPUT}
  "membrane speed +U_m = .* m/s: .*asks c0 >= 30 U_m = 4.5 m/s \\(c0 = 5\\)" --reject "LOW|WARNING"
  -- ${DMHS_EXE} -options_file ${DMHS_INPUT}/intestine-quick.opts -t_end 1e-5
  -output_snapshots false -output_dir ${DMHS_CLI_OUT}/slow-wave)
set_tests_properties(cli_intestine_wave_speed_ok PROPERTIES LABELS cli TIMEOUT 60)
# the peristaltic channel's pressure form: a deep wave (phi = 0.5) gets the symmetric form with
# the background pressure even where its throat (4 dx at ny = 8) has full support (the
# corrected operators let liquid through the wall there), a shallow one (phi = 0.2) the
# corrected operators
add_test(NAME cli_peristaltic_deep_wave_form COMMAND ${DMHS_EXPECT_OUTPUT}
  "background pressure 0\\.2372[0-9]* Pa" --reject "kernel correction"
  -- ${DMHS_EXE} -options_file ${DMHS_INPUT}/peristaltic_channel.opts -t_end 1e-6
  -output_snapshots false -output_dir ${DMHS_CLI_OUT}/peristaltic-deep)
set_tests_properties(cli_peristaltic_deep_wave_form PROPERTIES LABELS cli TIMEOUT 60)
add_test(NAME cli_peristaltic_shallow_wave_form COMMAND ${DMHS_EXPECT_OUTPUT}
  "background pressure 0\\. Pa.*sph: kernel correction"
  -- ${DMHS_EXE} -options_file ${DMHS_INPUT}/peristaltic_channel.opts -peristaltic_b 0.2e-3
  -t_end 1e-6 -output_snapshots false -output_dir ${DMHS_CLI_OUT}/peristaltic-shallow)
set_tests_properties(cli_peristaltic_shallow_wave_form PROPERTIES LABELS cli TIMEOUT 60)
# scripts/vein_study.sh: two tiny runs at a time, stopped by SIGTERM with checkpoints, continued to
# the same rows as an uninterrupted study, completed runs skipped, a clot run by seed, --collect
# (test/cli/vein_study_driver.sh)
add_test(NAME cli_vein_study_driver COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/vein_study_driver.sh ${PROJECT_SOURCE_DIR}
  ${DMHS_EXE} ${DMHS_CLI_OUT}/vein-study-driver)
set_tests_properties(cli_vein_study_driver PROPERTIES LABELS cli TIMEOUT 300 PROCESSORS 2)
# one option per message, with its value
dmhs_cli_fail(cli_vein_bad_ka "-vein_leaflet_ka must be >= 0 J \\(got -1"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -vein_leaflet_ka -1 -output_dir ${DMHS_CLI_OUT}/vein-bad-ka)
dmhs_cli_fail(cli_vein_bad_root "-vein_leaflet_root pinned: unknown value; -vein_leaflet_root takes one of clamped, hinged"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -vein_leaflet_root pinned -output_dir ${DMHS_CLI_OUT}/vein-bad-root)
dmhs_cli_fail(cli_vein_bad_wall_layers "-vein_wall_layers must be >= 1 \\(got 0\\)"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -vein_wall_layers 0 -output_dir ${DMHS_CLI_OUT}/vein-bad-layers)
# one option per message, its value and its range, in the other scenes and modules too
dmhs_cli_fail(cli_box_bad_nx "-box_nx must be > 0 \\(got 0\\)"
  -scene box -box_nx 0 -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/box-bad-nx)
dmhs_cli_fail(cli_flap_bad_column "-flap_column must lie in \\[0, 38\\] \\(-flap_nx - 2; got 999\\)"
  -scene flap -flap_column 999 -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/flap-bad-column)
dmhs_cli_fail(cli_intestine_bad_weir "-intestine_weir must be >= 0 m \\(got -1"
  -scene intestine -intestine_weir -1 -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/intestine-bad-weir)
dmhs_cli_fail(cli_sph_bad_av_beta "-sph_av_beta must be >= 0 \\(got -1"
  -scene box -sph_av_beta -1 -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/sph-bad-beta)
dmhs_cli_fail(cli_repulsion_bad_p1 "-repulsion_p1 must lie in \\[3, 24\\] .*got 2\\)"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -repulsion_p1 2 -repulsion_p2 2 -output_dir ${DMHS_CLI_OUT}/repulsion-bad-p1)
dmhs_cli_fail(cli_repulsion_substeps_without_substeps "-repulsion_substeps runs the repulsion on the solid sub-steps, but there are none \\(-solid_substeps 1\\)"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -repulsion_substeps -output_dir ${DMHS_CLI_OUT}/repulsion-substeps-alone)
dmhs_cli_fail(cli_solid_substeps_bad_scheme "-solid_substeps_scheme middle: unknown value; -solid_substeps_scheme takes one of respa, held"
  -options_file ${DMHS_INPUT}/vein-quick.opts -quiet -solid_substeps 0 -solid_substeps_scheme middle -output_dir ${DMHS_CLI_OUT}/substeps-bad-scheme)
dmhs_cli_fail(cli_snapshot_every_zero "-snapshot_every must be >= 1 \\(got 0\\)"
  -scene poiseuille -snapshot_every 0 -t_end 1e-6 -quiet -output_dir ${DMHS_CLI_OUT}/snapshot-every-zero)
