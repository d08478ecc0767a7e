# Rank-count invariance (doc/parallel.md). The same run on 1..4
# ranks must give the same gid-sorted final particle states (-dump_final);
# compare_dumps.py measures max|a - b| / max|a| per column and fails above
# 1e-10 (the runs are in fact bitwise identical: cells order rows by gid).
set(DMHS_MPI_OUT ${CMAKE_CURRENT_BINARY_DIR}/mpi_out)
file(MAKE_DIRECTORY ${DMHS_MPI_OUT})
set(DMHS_COMPARE ${DMHS_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/compare_dumps.py --tol 1e-10)

# name: test prefix; ranks: list of rank counts (the first is the reference);
# remaining arguments: dmhs options.
function(dmhs_mpi_invariance name ranks)
  set(dumps)
  list(GET ranks 0 ref)
  foreach(n ${ranks})
    set(dump ${DMHS_MPI_OUT}/${name}_np${n}.csv)
    add_test(NAME mpi_${name}_np${n}
      COMMAND ${DMHS_MPIRUN} -n ${n} ${DMHS_EXE} ${ARGN} -quiet
              -output_dir ${DMHS_MPI_OUT}/${name}_np${n} -dump_final ${dump})
    set_tests_properties(mpi_${name}_np${n} PROPERTIES LABELS mpi PROCESSORS ${n} TIMEOUT 600
      FIXTURES_SETUP ${name}_runs)
    if(NOT n EQUAL ref)
      list(APPEND dumps ${dump})
    endif()
  endforeach()
  add_test(NAME mpi_${name}_compare
    COMMAND ${DMHS_COMPARE} ${DMHS_MPI_OUT}/${name}_np${ref}.csv ${dumps})
  set_tests_properties(mpi_${name}_compare PROPERTIES LABELS mpi TIMEOUT 120 FIXTURES_REQUIRED ${name}_runs)
endfunction()

# Quick Poiseuille: 20 x 40 liquid + walls, 1000 steps (square lattice: 5e-4/20 = 1e-3/40).
dmhs_mpi_invariance(poiseuille "1;2;3;4"
  -options_file ${PROJECT_SOURCE_DIR}/input/poiseuille.opts
  -channel_nx 20 -channel_ny 40 -sph_h 7.5e-5 -dt 1e-4 -t_end 0.1)

# Flexible flap (bonds, angles, repulsion; partners resolved by gid through
# the ghosts), quick variant, 1000 steps.
dmhs_mpi_invariance(flap "1;2;3;4"
  -options_file ${PROJECT_SOURCE_DIR}/input/flap-quick.opts -t_end 0.01 -debug_migration)

# Migration stress: a strong Taylor-Green vortex (1 m/s over a 4 mm box) carries
# particles across many rank boundaries; -partition_imbalance 1.0001 forces a
# METIS repartition every 50 steps on top (tens of thousands of moves).
# -debug_migration checks the count and the gid set every step.
dmhs_mpi_invariance(migration "1;3;4"
  -scene box -box_nx 40 -box_ny 40 -box_velocity 1 -dt 2e-6 -t_end 2e-3
  -debug_migration -partition_imbalance 1.0001 -partition_interval 50)

# Halo vs brute force: -debug_halo compares, at every step, each owned
# particle's pair-list neighbours with a search over all ranks' particles.
foreach(n 2 3 4)
  add_test(NAME mpi_halo_box_np${n}
    COMMAND ${DMHS_MPIRUN} -n ${n} ${DMHS_EXE} -scene box -box_nx 30 -box_ny 24 -box_velocity 1
            -dt 2e-6 -t_end 2e-4 -debug_halo -debug_migration -partition_imbalance 1.0001
            -partition_interval 20 -quiet -output_dir ${DMHS_MPI_OUT}/halo_box_np${n})
  add_test(NAME mpi_halo_poiseuille_np${n}
    COMMAND ${DMHS_MPIRUN} -n ${n} ${DMHS_EXE} -options_file ${PROJECT_SOURCE_DIR}/input/poiseuille.opts
            -channel_nx 20 -channel_ny 40 -sph_h 7.5e-5 -dt 1e-4 -t_end 0.01 -debug_halo -quiet
            -output_dir ${DMHS_MPI_OUT}/halo_poiseuille_np${n})
  set_tests_properties(mpi_halo_box_np${n} mpi_halo_poiseuille_np${n} PROPERTIES LABELS mpi PROCESSORS ${n}
    TIMEOUT 300)
endforeach()

# The first Parallel criterion: two ranks give the same error table as one.
foreach(n 1 2)
  add_test(NAME mpi_poiseuille_errors_np${n}
    COMMAND ${DMHS_MPIRUN} -n ${n} ${DMHS_EXE} -options_file ${PROJECT_SOURCE_DIR}/input/poiseuille.opts
            -t_end 0.05 -quiet -output_dir ${DMHS_MPI_OUT}/errors_np${n})
  set_tests_properties(mpi_poiseuille_errors_np${n} PROPERTIES LABELS mpi PROCESSORS ${n} TIMEOUT 300
    FIXTURES_SETUP poiseuille_errors)
endforeach()
add_test(NAME mpi_poiseuille_errors_compare
  COMMAND ${CMAKE_COMMAND} -E compare_files ${DMHS_MPI_OUT}/errors_np1/profile_t0.01.csv
          ${DMHS_MPI_OUT}/errors_np2/profile_t0.01.csv)
set_tests_properties(mpi_poiseuille_errors_compare PROPERTIES LABELS mpi FIXTURES_REQUIRED poiseuille_errors)
