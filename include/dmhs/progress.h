/* What rank 0 tells the user while a run goes (src/driver/progress.c): a status line at a
 * simulated-time interval and at a wall-clock one, a projection of the whole run after its
 * first steps, and the one-line summary at the end.
 *
 * When a status line comes, after a step:
 *   - every -progress_interval of simulated time (identical on every rank: t is);
 *   - when -progress_wall_interval seconds of wall time have passed since the last line, and
 *     PROGRESS_FIRST_WALL seconds after the step loop started if no line came before (a long
 *     run's first sign of life). Rank 0's clock decides (the ranks' clocks differ): the step
 *     loop's one reduction after each step, the one that agrees on stop signals, carries its
 *     answer, so the wall-clock lines cost no communication of their own;
 *   - PROGRESS_PROJECTION_STEPS steps into the session (a restart counts from its checkpoint),
 *     followed by the projection line: the steps to t_end, the wall time and the clock time
 *     the run ends at.
 * The ETA of every line is the steps left at the current dt times the mean wall time of this
 * session's steps: with the automatic dt (-dt 0) the count follows dt as it changes.
 * Each line is also a heartbeat in run.json (io_heartbeat), with -quiet as well (which only
 * silences the lines). Nothing here changes the state: the physics is the same with or
 * without the lines. */
#ifndef DMHS_PROGRESS_H
#define DMHS_PROGRESS_H
#include <petscsys.h>

/* Wall seconds from the start of the step loop to the first line, when none came before. */
#define PROGRESS_FIRST_WALL 30.0
/* -progress_wall_interval's default [s]. */
#define PROGRESS_WALL_INTERVAL_DEFAULT 600.0
/* Steps of a session after which the projection line is printed. */
#define PROGRESS_PROJECTION_STEPS 100

typedef struct progress_clock {
  double wall_interval;   /* -progress_wall_interval [s]; 0: no wall-clock lines */
  double last_line_wtime; /* rank 0: MPI_Wtime of the last line, or of the loop's start */
  PetscInt first_step;    /* the step this session's loop started from */
  PetscBool any_line;     /* a line came in this session */
} progress_clock;

struct sim;
struct run_control;
/* -progress_interval, -progress_wall_interval, -quiet (in the run-control section). */
PetscErrorCode progress_set_from_options(struct sim *s, struct run_control *rc);
/* At the start of the step loop: the session's first step and clock. */
void progress_start(struct sim *s, struct run_control *rc);
/* Rank 0's clock: is a wall-clock line due? (Plain: the step loop reduces the answer.) */
PetscBool progress_wall_due(const struct run_control *rc);
/* After a step, on every rank with the same wall_due: the status line (and the projection)
 * when one is due, unless -quiet, and then the heartbeat. */
PetscErrorCode progress_after_step(struct sim *s, struct run_control *rc, PetscBool wall_due);
/* Final line, always printed (also with -quiet): includes "particle-steps/s: <value>". */
PetscErrorCode progress_summary(struct sim *s, const struct run_control *rc);

#endif
