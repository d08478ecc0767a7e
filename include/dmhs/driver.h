/* The driver (src/driver/run.c): a run from the options to the last output.
 * main: sim_create -> sim_run -> sim_destroy. */
#ifndef DMHS_DRIVER_H
#define DMHS_DRIVER_H
#include "dmhs/sim.h"

/* The options pass, the scene and its modules, the particles, ghosts and the pre-flight
 * report, forces at t = 0 (and a restart's state); help_only: -help was asked for and
 * listed, nothing else was set up. */
PetscErrorCode sim_create(MPI_Comm comm, sim **out, PetscBool *help_only);
/* The step loop to t_end (or a stop signal), then the end-of-run reports and files. */
PetscErrorCode sim_run(sim *s);
PetscErrorCode sim_destroy(sim **s);
/* The force evaluation of a step on the current positions: every enabled module (with
 * -solid_substeps, the solids' own share kept apart: substep.c). */
PetscErrorCode sim_compute_forces(sim *s);

#endif
