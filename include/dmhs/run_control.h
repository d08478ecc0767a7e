/* The driver's run control: the time step's state, the output schedule and the progress
 * lines. The core state (sim) holds the time itself (t, dt, step, t_end) and, for one step
 * at a time, whether its state is an output (sim.output_step, set from this schedule); the
 * layers below the driver see nothing else of it. */
#ifndef DMHS_RUN_CONTROL_H
#define DMHS_RUN_CONTROL_H
#include <petscsys.h>
#include "dmhs/timestep.h"
#include "dmhs/progress.h"

typedef struct run_control {
  timestep ts; /* fixed-dt check or automatic dt (timestep.c) */
  /* the output schedule: rows and snapshots every output_interval of physical time */
  double output_interval, next_output_t;
  PetscInt last_output_step;           /* the step of the last output (-1: none in this session) */
  char output_dir[PETSC_MAX_PATH_LEN]; /* -output_dir: created by the driver, given to io */
  /* progress lines (progress.c) */
  double progress_interval, next_progress_t;
  progress_clock progress;
  PetscBool quiet;
  PetscInt64 particle_steps; /* owned particles x steps, summed over ranks */
} run_control;

struct sim;
/* Whether the state at s's time is an output of the schedule: t within dt/2 of the next
 * output time. */
PetscBool run_control_output_due(const run_control *rc, const struct sim *s);
/* The output's number, t / output_interval rounded: the same for a step across a restart. */
PetscInt64 run_control_output_number(const run_control *rc, const struct sim *s);
/* Whether s is at the run's end: t within dt/2 of t_end (the step loop stops there). */
PetscBool run_control_at_end(const struct sim *s);

#endif
