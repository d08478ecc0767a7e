/* Error of the liquid's v_x against an exact solution, written as the run goes:
 * <output_dir>/error.csv (step,t,wall_s,l2,linf) every output interval, where
 * l2 is the RMS and linf the max of (v_x - v_exact) / v_ref over fluid particles;
 * at each report time (default 0.01, 0.1, 1 s) also profile_t<t>.csv
 * (y,vx,vx_exact per fluid particle), and a table at the end of the run.
 * v_ref is one fixed speed for the whole run, chosen by the scene: the steady peak
 * F l^2/(8 nu) (Poiseuille), the plate speed (Couette), and for a pulsatile drive
 * g0 sin(w t) the steady-periodic centreline amplitude |g0/(i w) (1 - 1/cosh(kappa a))|,
 * kappa = sqrt(i w/nu): a pulsatile flow passes through zero, so an error relative to
 * the current speed would be unbounded there. */
#ifndef DMHS_ERRORS_H
#define DMHS_ERRORS_H
#include <petscsys.h>

struct sim;
struct checkpoint_io;
typedef double (*errors_exact_fn)(double y, double t, const void *ctx);

#define ERRORS_MAX_REPORTS 16
typedef struct errors {
  errors_exact_fn exact;
  const void *ctx;
  double v_ref; /* normalisation [m/s], fixed for the run */
  FILE *csv;    /* rank 0 only */
  PetscInt n_reports, next_report;
  double report_t[ERRORS_MAX_REPORTS];
  double reached_t[ERRORS_MAX_REPORTS], l2[ERRORS_MAX_REPORTS], linf[ERRORS_MAX_REPORTS],
      wall_s[ERRORS_MAX_REPORTS];
} errors;

/* Reads -error_report_times (a list of times [s]). */
PetscErrorCode errors_set_from_options(errors *e, struct sim *s);
PetscErrorCode errors_setup(errors *e, struct sim *s, errors_exact_fn exact, const void *ctx,
                            double v_ref);
/* Per step: appends a row at output times, records and writes profiles at report times. */
PetscErrorCode errors_on_step(errors *e, struct sim *s);
/* Prints the errors at the report times reached and the wall-clock time. */
PetscErrorCode errors_report(errors *e, struct sim *s);
PetscErrorCode errors_destroy(errors *e);
/* Checkpoint hooks: the reports done so far; on restart error.csv is continued. */
PetscErrorCode errors_checkpoint_write(errors *e, struct checkpoint_io *io);
PetscErrorCode errors_checkpoint_read(errors *e, struct sim *s, struct checkpoint_io *io);
/* Normalised RMS and max error over owned fluid particles, reduced over ranks. */
PetscErrorCode errors_compute(errors *e, struct sim *s, double *l2, double *linf);

#endif
