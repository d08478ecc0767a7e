/* struct sim, the core state: domain, particles, ghosts, cells, topology, the enabled
 * modules, the time and the step's sub-steps. The upper layers' own state (io's, the
 * scene) is theirs: sim only points to it, through forward-declared structs, and a file that
 * reads it includes its header; the driver's run control (time step, output schedule,
 * progress) is the driver's alone (run_control.h). The
 * run (setup, the step loop) is the driver's (src/driver/run.c, run.h); neighbour
 * handling is neighbours.c. */
#ifndef DMHS_SIM_H
#define DMHS_SIM_H
#include <petscsys.h>
#include "dmhs/particles.h"
#include "dmhs/domain.h"
#include "dmhs/halo.h"
#include "dmhs/cells.h"
#include "dmhs/module.h"
#include "dmhs/diagnostic.h"
#include "dmhs/partition.h" /* mpi */
#include "dmhs/migrate.h"   /* mpi */
#include "dmhs/topology.h"
#include "dmhs/options.h" /* checked option readers, in every module */
#include "dmhs/substep.h"

#define SIM_MAX_MODULES 16

typedef struct sim {
  MPI_Comm comm;
  PetscMPIInt rank, size;

  /* the time: the driver's run control (run_control.h) advances it */
  double t, dt, t_end;
  PetscBool t_end_given; /* -t_end was given: a scene's default does not apply */
  PetscInt step;
  /* t = t_anchor + (step - step_anchor) dt: the time and step of the last dt change */
  double t_anchor;
  PetscInt step_anchor;
  substep_plan substeps; /* the solids' sub-steps of this step (set by timestep.c) */
  /* this step's state is an output: rows at outputs, a snapshot (set by the driver's schedule
   * around the step's diagnostics and output, diagnostic_output_time) */
  PetscBool output_step;

  /* state */
  domain dom;
  double dx; /* rest particle spacing [m], set by the scene */
  particles ps;
  halo hal;
  cells cel;
  double pair_cutoff; /* largest pair reach among modules that need pairs */
  double skin_ratio;  /* -neighbour_skin: Verlet skin as a fraction of the longest reach */
  double skin;        /* [m]; ghosts and pairs reach this much further than any interaction */
  double list_cutoff; /* pair_cutoff + skin: the pair list's radius */
  PetscInt n_rebuilds;
  PetscBool force_rebuild; /* a module changed the structure (post_step): the next step rebuilds */
  /* a and drho of the owned rows hold nothing yet: the evaluation's first module sets them
   * (MODULE_SETS_RATES) and clears this; every other compute adds to them */
  PetscBool rates_unset;
  /* what a step refreshes on ghosts between builds: the union of the modules' ghost_reads,
   * in field-table order (sim_collect_ghost_reads) */
  const char *ghost_step_fields[32];
  int n_ghost_step_fields;
  /* mpi: domain decomposition, migration check, debug and dump options */
  partition part;
  migrate_check mig;
  PetscBool debug_halo;                /* -debug_halo: pair list vs brute force, every rebuild */
  char dump_final[PETSC_MAX_PATH_LEN]; /* -dump_final <file> */

  /* physics: each module owns its parameters (sph_params_get, body_force_get, ...) */
  topology *topo; /* bonds and angles (solids); NULL in scenes without solids */
  module *modules[SIM_MAX_MODULES];
  int n_modules;
  const char *scene_name; /* the scene's name, for messages and files (the driver has the scene) */
  /* what the scene measures, sampled after the steps of each one's schedule (diagnostic.h) */
  diagnostic *diagnostics[SIM_MAX_DIAGNOSTICS];
  int n_diagnostics;

  /* timing: the step loop's wall clock */
  double loop_start_wtime, loop_seconds;

  /* snapshots, checkpoints, restart, run.json (src/io/io.c) */
  struct io_state *io;
} sim;

/* A scene's default run length, in its set_from_options: t_end unless -t_end was given; the
 * output and progress intervals left at 0 follow it (t_end/100, t_end/20). */
void sim_default_t_end(sim *s, double t_end);
/* The enabled module of that registry name, or NULL. */
module *sim_find_module(const sim *s, const char *name);
/* Which modules a force evaluation runs: those for which it is true. */
typedef PetscBool (*module_filter)(const module *m);
/* Zeroes a and drho of the owned and ghost rows, then sim_add_module_forces. When the first
 * module it runs sets the owned rows' itself (MODULE_SETS_RATES), only the ghost rows' are
 * zeroed and sim's rates_unset tells that module to start from zero. */
PetscErrorCode sim_compute_module_forces(sim *s, module_filter keep);
/* The two phases of a force evaluation over the enabled modules keep accepts (NULL: all):
 * every prepare, then every compute, each in the order the modules were enabled; the
 * computes add to a and drho. */
PetscErrorCode sim_add_module_forces(sim *s, module_filter keep);

#endif
