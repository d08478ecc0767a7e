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
typedef double (*errors_exact_fn)(double y, double t, const void *ctx);

#define ERRORS_MAX_REPORTS 16
/* The report times [s], increasing. */
typedef struct errors_times {
  PetscInt n;
  double t[ERRORS_MAX_REPORTS];
} errors_times;

/* Reads -error_report_times (a list of times [s]; default 0.01, 0.1, 1 s). */
PetscErrorCode errors_set_from_options(errors_times *times, struct sim *s);
/* Registers the diagnostic "errors" (error.csv, profiles, the end-of-run table) against
 * exact(y, t, ctx), normalised by v_ref [m/s] > 0; ctx must outlive the run. */
PetscErrorCode errors_register(struct sim *s, const errors_times *times, errors_exact_fn exact,
                               const void *ctx, double v_ref);

#endif
