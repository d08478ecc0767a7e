/* Progress lines, the projection and the end-of-run summary (rank 0 prints); when a line
 * comes: progress.h. */
#include <math.h>
#include <time.h>
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/sph.h"
#include "dmhs/progress.h"
#include "dmhs/run_control.h"

PetscErrorCode progress_set_from_options(sim *s, run_control *rc) {
  progress_clock *pc = &rc->progress;
  PetscFunctionBeginUser;
  pc->wall_interval = PROGRESS_WALL_INTERVAL_DEFAULT;
  PetscOptionsBegin(s->comm, NULL, "dmhs run control", NULL);
  PetscCall(options_read_real("-progress_interval",
                              "Physical time between progress lines [s] (0 = t_end/20)", NULL,
                              rc->progress_interval, &rc->progress_interval, NULL));
  PetscCall(options_run_control("-progress_interval"));
  PetscCall(options_read_real(
      "-progress_wall_interval",
      "Wall-clock time after which a progress line comes if none came (the first after at most "
      "30 s) [s] (0 = none: -progress_interval only)",
      NULL, pc->wall_interval, &pc->wall_interval, NULL));
  PetscCall(options_run_control("-progress_wall_interval"));
  PetscCall(
      options_read_bool("-quiet", "Silence the progress lines", NULL, rc->quiet, &rc->quiet, NULL));
  PetscCall(options_run_control("-quiet"));
  PetscOptionsEnd();
  PetscCheck(rc->progress_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-progress_interval must be >= 0 s (got %g)", rc->progress_interval);
  PetscCheck(pc->wall_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-progress_wall_interval must be >= 0 s (got %g; 0 = no wall-clock lines)",
             pc->wall_interval);
  PetscFunctionReturn(0);
}

void progress_start(sim *s, run_control *rc) {
  rc->progress.first_step = s->step;
  rc->progress.last_line_wtime = s->loop_start_wtime;
  rc->progress.any_line = PETSC_FALSE;
}

PetscBool progress_wall_due(const run_control *rc) {
  const progress_clock *pc = &rc->progress;
  if (pc->wall_interval <= 0)
    return PETSC_FALSE;
  const double wait =
      pc->any_line ? pc->wall_interval : PetscMin(PROGRESS_FIRST_WALL, pc->wall_interval);
  return MPI_Wtime() - pc->last_line_wtime >= wait ? PETSC_TRUE : PETSC_FALSE;
}

/* Where the run stands against its end, from rank 0's clock. */
typedef struct {
  double steps_left;    /* at the current dt */
  double step_seconds;  /* mean wall time of this session's steps */
  double seconds_left;  /* steps_left x step_seconds */
  double seconds_spent; /* since the step loop started */
} progress_outlook;

static progress_outlook progress_look_ahead(const sim *s, const run_control *rc) {
  progress_outlook o;
  const PetscInt done = s->step - rc->progress.first_step;
  /* the loop stops at the step nearest t_end: the first t >= t_end - dt/2 */
  const double to_go = (s->t_end - s->t) / s->dt - 0.5;
  o.steps_left = to_go > 0 ? ceil(to_go) : 0.0;
  o.seconds_spent = MPI_Wtime() - s->loop_start_wtime;
  o.step_seconds = done > 0 ? o.seconds_spent / (double)done : 0.0;
  o.seconds_left = o.steps_left * o.step_seconds;
  return o;
}

/* "4.2 s", "42 s", "12m 05s", "3h 07m", "2d 05h": as precise as a projection can be. */
static void progress_format_duration(double seconds, char *text, size_t len) {
  const long s = lround(seconds);
  if (seconds < 9.95)
    snprintf(text, len, "%.1f s", seconds > 0 ? seconds : 0.0); /* never "-0.0 s" */
  else if (s < 60)
    snprintf(text, len, "%ld s", s);
  else if (s < 3600)
    snprintf(text, len, "%ldm %02lds", s / 60, s % 60);
  else if (s < 86400)
    snprintf(text, len, "%ldh %02ldm", s / 3600, (s % 3600) / 60);
  else
    snprintf(text, len, "%ldd %02ldh", s / 86400, (s % 86400) / 3600);
}

/* The local clock time seconds from now, "2026-12-05 14:32" ("?" if the clock fails). */
static void progress_format_clock(double seconds, char *text, size_t len) {
  const time_t at = time(NULL) + (time_t)lround(seconds);
  struct tm local;
  if (!localtime_r(&at, &local) || !strftime(text, len, "%Y-%m-%d %H:%M", &local))
    snprintf(text, len, "?");
}

static double particle_steps_per_second(const run_control *rc, double seconds) {
  return seconds > 0 ? (double)rc->particle_steps / seconds : 0.0;
}

static PetscErrorCode progress_print(sim *s, const run_control *rc, const progress_outlook *o) {
  const particles *ps = &s->ps;
  const sph_params *sp = sph_params_get(s); /* NULL: no liquid (solids only) */
  double local[2] = {0, 0}, global[2];
  char eta[32], ends[32];
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    local[0] = PetscMax(local[0], ps->v[i][0] * ps->v[i][0] + ps->v[i][1] * ps->v[i][1]);
    if (ps->type[i] == PTYPE_FLUID && sp)
      local[1] = PetscMax(local[1], PetscAbsReal(ps->rho[i] / sp->rho0 - 1.0));
  }
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, s->comm));
  PetscCall(partition_measure_imbalance(&s->part, s)); /* mpi: max/mean owned over ranks */
  progress_format_duration(o->seconds_left, eta, sizeof(eta));
  progress_format_clock(o->seconds_left, ends, sizeof(ends));
  PetscCall(PetscPrintf(s->comm,
                        "step %8" PetscInt_FMT
                        "  t %.6e s  dt %.3e s (%s)  particle-steps/s %.3e  ETA %s (%s)  "
                        "max|v| %.3e m/s  max|rho/rho0-1| %.2e  imbalance %.3f\n",
                        s->step, s->t, s->dt, rc->ts.binding[0] ? rc->ts.binding : "no limit",
                        particle_steps_per_second(rc, o->seconds_spent), eta, ends, sqrt(global[0]),
                        global[1], s->part.imbalance));
  PetscFunctionReturn(0);
}

/* After the first steps: how many steps the run takes, how long and when it ends. */
static PetscErrorCode progress_print_projection(sim *s, const run_control *rc,
                                                const progress_outlook *o) {
  const double steps_total = (double)s->step + o->steps_left;
  char total[32], left[32], ends[32], t_end[32];
  PetscFunctionBeginUser;
  progress_format_duration(o->seconds_spent + o->seconds_left, total, sizeof(total));
  progress_format_duration(o->seconds_left, left, sizeof(left));
  progress_format_clock(o->seconds_left, ends, sizeof(ends));
  snprintf(t_end, sizeof(t_end), "%g", s->t_end); /* C's %g: PETSc's prints "16." */
  PetscCall(PetscPrintf(
      s->comm,
      "projection after %d steps: %.0f steps to t_end = %s s, %s of wall time (%s to go at "
      "%.3e s per step), ending about %s local time%s\n",
      PROGRESS_PROJECTION_STEPS, steps_total, t_end, total, left, o->step_seconds, ends,
      rc->ts.adaptive ? "; the automatic dt changes with the state, and the count with it" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode progress_after_step(sim *s, run_control *rc, PetscBool wall_due) {
  progress_clock *pc = &rc->progress;
  PetscFunctionBeginUser;
  const PetscBool interval_due =
      s->t >= rc->next_progress_t - 0.5 * s->dt ? PETSC_TRUE : PETSC_FALSE;
  const PetscBool projection_due =
      s->step - pc->first_step == PROGRESS_PROJECTION_STEPS ? PETSC_TRUE : PETSC_FALSE;
  if (interval_due)
    rc->next_progress_t += rc->progress_interval;
  if (!interval_due && !projection_due && !wall_due)
    PetscFunctionReturn(0);
  if (!rc->quiet) {
    const progress_outlook o = progress_look_ahead(s, rc); /* one clock reading for both lines */
    PetscCall(progress_print(s, rc, &o));
    if (projection_due)
      PetscCall(progress_print_projection(s, rc, &o));
  }
  pc->last_line_wtime = MPI_Wtime();
  pc->any_line = PETSC_TRUE;
  PetscCall(io_heartbeat(s)); /* run.json: this run is alive */
  PetscFunctionReturn(0);
}

PetscErrorCode progress_summary(sim *s, const run_control *rc) {
  PetscInt n_owned = s->ps.n_owned, n_total;
  char t_text[32];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&n_owned, &n_total, 1, MPIU_INT, MPI_SUM, s->comm));
  snprintf(t_text, sizeof(t_text), "%g", s->t); /* C formatting: PETSc's %g prints "1." */
  PetscCall(
      PetscPrintf(s->comm,
                  "dmhs summary: scene %s, %" PetscInt_FMT " particles, %d rank(s), %" PetscInt_FMT
                  " steps to t = %s s, %" PetscInt_FMT " neighbour-list builds, step loop %.3f s, "
                  "particle-steps/s: %.4e\n",
                  s->scene_name, n_total, (int)s->size, s->step, t_text, s->n_rebuilds,
                  s->loop_seconds, particle_steps_per_second(rc, s->loop_seconds)));
  PetscFunctionReturn(0);
}
