/* The driver (src/driver/run.c): a run from the options to the last output.
 * main: run_create -> run_steps -> run_destroy. */
#ifndef DMHS_RUN_H
#define DMHS_RUN_H
#include "dmhs/sim.h"
#include "dmhs/run_control.h"

/* A run: the core state, the driver's own run control (time step, output schedule,
 * progress) and the scene, which the layers below never see. */
struct scene;
typedef struct dmhs_run {
  sim *core;
  run_control control;
  struct scene *scn; /* the scene (scene.h): its hooks are called by the driver only */
} dmhs_run;

/* The options pass, the scene and its modules, the particles, ghosts and the pre-flight
 * report, forces at t = 0 (and a restart's state); help_only: -help was asked for and
 * listed, nothing else was set up. */
PetscErrorCode run_create(MPI_Comm comm, dmhs_run **out, PetscBool *help_only);
/* The step loop to t_end (or a stop signal), then the end-of-run reports and files. */
PetscErrorCode run_steps(dmhs_run *r);
PetscErrorCode run_destroy(dmhs_run **r);
/* The core state's teardown (with what it holds: diagnostics, modules, io's state). */
PetscErrorCode sim_destroy(sim **s);
/* The force evaluation of a step on the current positions: every enabled module (with
 * -solid_substeps, the solids' own share kept apart: substep.c). */
PetscErrorCode sim_compute_forces(sim *s);

#endif
