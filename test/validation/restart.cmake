# Restart equivalence scene by scene: test/io/restart_scene.sh runs
# a scene to t_end in one go and to t_end/2 + -restart, possibly on other rank
# counts, and compares every output file (snapshots and checkpoint by gid,
# bitwise; XDMF; every CSV but its wall-clock columns). Labels io, mpi.
set(DMHS_RESTART_OUT ${CMAKE_BINARY_DIR}/test-output/restart)
set(DMHS_RESTART_SCENE bash ${CMAKE_CURRENT_LIST_DIR}/../io/restart_scene.sh ${DMHS_EXE} ${DMHS_PYTHON}
    ${DMHS_MPIRUN} --)

# name; ranks of the uninterrupted run, of the first half, of the restarted half; t_end; options...
# A name ending in _past runs restart_scene.sh --past.
function(dmhs_restart_test name np_ref np_first np_second t_end)
  set(mode)
  if(name MATCHES "_past$")
    set(mode --past)
  endif()
  add_test(NAME ${name} COMMAND ${DMHS_RESTART_SCENE} ${mode} ${DMHS_RESTART_OUT}/${name} ${np_ref} ${np_first}
           ${np_second} ${t_end} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "io;mpi" PROCESSORS 2 TIMEOUT 180)
endfunction()

# The flap on 1 -> 1, 2 -> 2 and 1 -> 2 ranks (2 -> 1: io_restart_flap_quick
# below), checkpoint between two output times (flap.csv continued, crossing
# counter restored, flap-particles.csv in gid order).
foreach(np "1;1;1" "2;2;2" "1;1;2")
  list(GET np 0 ref)
  list(GET np 1 first)
  list(GET np 2 second)
  dmhs_restart_test(io_restart_flap_np${first}to${second} ${ref} ${first} ${second} 0.01
                    -options_file ${PROJECT_SOURCE_DIR}/input/flap-quick.opts)
endforeach()

# The cantilever (no liquid): cantilever.csv continued after the restart. Its
# default output interval is t_end/100, so it is fixed here for both halves.
dmhs_restart_test(io_restart_cantilever 2 2 1 0.002 -options_file ${PROJECT_SOURCE_DIR}/input/cantilever.opts
                  -output_interval 1e-4)

# Every quick input (new scenes' inputs/*-quick.opts are picked up when CMake
# configures): 2 ranks to t = 0.02 s against 2 ranks to 0.01 s + restart on 1.
file(GLOB DMHS_QUICK_INPUTS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/input/*-quick.opts)
foreach(opts ${DMHS_QUICK_INPUTS})
  get_filename_component(case ${opts} NAME_WE)
  string(REPLACE "-" "_" case ${case})
  dmhs_restart_test(io_restart_${case} 2 2 1 0.02 -options_file ${opts})
  # the first run goes on past its checkpoint (killed later): its rows and snapshots are replaced
  dmhs_restart_test(io_restart_${case}_past 2 2 1 0.02 -options_file ${opts})
endforeach()
