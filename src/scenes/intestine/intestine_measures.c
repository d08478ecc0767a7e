/* The colon's measures (intestine_measures.h; doc/theory.md, "Peristalsis and
 * tracking"), from the rows (t, x_F, alpha) the diagnostic "intestine" keeps:
 *
 *   line over [t0, t1]:  x ~ x0 + slope (t - t0), least squares (GSL),
 *                        R^2 = 1 - sum (x - line)^2 / sum (x - mean x)^2
 *   whole waves:         n = floor((t_last - t_d)/T_w), capped by the schedule's waves
 *   u_F                = slope over [t_d, t_d + n T_w] when its R^2 >= r2_min
 *                        or n <= n_i; else the initial slope, over
 *                        [t_d, t_d + n_i T_w]
 *   u_P                = alpha/(1 - alpha) V_w/(N+1),  u_S = alpha V_w
 *   Re                 = b u/nu for u > 0
 *
 * The thesis fits its line to x_F over the whole run (ten waves) and takes the
 * initial slope where x_F bends (the level drops and the front steepens, or the
 * liquid splits into pools and it stalls). A line over whole waves leaves out the
 * part of a wave that the run's end would cut: each wave's pulse (the front
 * goes forward while pocket 0 squeezes and partly back as it relaxes) then
 * weighs the same in every window. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include "intestine_measures.h"

PetscInt intestine_measures_whole_waves(double t_last, double t_d, double T_w, PetscInt waves_max,
                                        double tol) {
  if (!(T_w > 0) || !isfinite(t_last) || !isfinite(t_d) || t_last + tol < t_d)
    return 0;
  const double w = floor((t_last - t_d + tol) / T_w);
  PetscInt n = w > 1e9 ? 1000000000 : (PetscInt)w;
  if (waves_max > 0 && n > waves_max)
    n = waves_max;
  return n < 0 ? 0 : n;
}

PetscErrorCode intestine_measures_line(const double *t, const double *x, PetscInt n, double t0,
                                       double t1, double tol, intestine_line *line) {
  PetscInt i0 = -1, m = 0;
  PetscFunctionBeginUser;
  line->t0 = t0;
  line->t1 = t1;
  line->slope = line->x0 = line->r2 = NAN;
  line->n = 0;
  for (PetscInt i = 0; i < n; i++)
    if (t[i] >= t0 - tol && t[i] <= t1 + tol) {
      if (i0 < 0)
        i0 = i;
      m++;
    }
  line->n = m;
  if (m < 2)
    PetscFunctionReturn(0);
  /* the rows are in time order: the window is contiguous */
  PetscCheck(i0 + m <= n && t[i0 + m - 1] <= t1 + tol, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "intestine_measures_line: rows not in time order");
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_set_error_handler_off();
  const int err =
      gsl_fit_linear(t + i0, 1, x + i0, 1, (size_t)m, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_LIB, "gsl_fit_linear: %s", gsl_strerror(err));
  double mean = 0, sstot = 0;
  for (PetscInt i = i0; i < i0 + m; i++)
    mean += x[i];
  mean /= (double)m;
  for (PetscInt i = i0; i < i0 + m; i++)
    sstot += (x[i] - mean) * (x[i] - mean);
  line->slope = c1;
  line->x0 = c0 + c1 * t0;
  /* a constant x is fitted exactly (slope 0): R^2 = 1, not 0/0 */
  line->r2 = sstot > 0 ? 1.0 - sumsq / sstot : 1.0;
  PetscFunctionReturn(0);
}

PetscErrorCode intestine_measures_front(const double *t, const double *x, PetscInt n, double t_d,
                                        double T_w, PetscInt waves_max, PetscInt initial_waves,
                                        double r2_min, double tol, intestine_front *f) {
  PetscFunctionBeginUser;
  PetscCheck(initial_waves >= 1 && r2_min > 0 && r2_min <= 1, PETSC_COMM_SELF,
             PETSC_ERR_ARG_OUTOFRANGE,
             "intestine_measures_front: initial_waves must be >= 1 and 0 < r2_min <= 1");
  memset(f, 0, sizeof(*f));
  f->u_F = NAN;
  f->from_initial = PETSC_FALSE;
  f->waves = n > 0 ? intestine_measures_whole_waves(t[n - 1], t_d, T_w, waves_max, tol) : 0;
  const PetscInt ni = PetscMin(f->waves, initial_waves);
  PetscCall(intestine_measures_line(t, x, n, t_d, t_d + f->waves * T_w, tol, &f->line));
  PetscCall(intestine_measures_line(t, x, n, t_d, t_d + ni * T_w, tol, &f->initial));
  PetscCall(intestine_measures_line(t, x, n, t_d, t_d + T_w, tol, &f->first_wave));
  if (f->waves < 1) {
    f->line.slope = f->line.x0 = f->line.r2 = NAN;
    f->initial.slope = f->initial.x0 = f->initial.r2 = NAN;
    f->first_wave.slope = f->first_wave.x0 = f->first_wave.r2 = NAN;
    if (n > 0)
      PetscCall(PetscSNPrintf(f->why, sizeof(f->why),
                              "no whole wave: the rows end at %.6g s < t_d + T_w = %.6g s",
                              t[n - 1], t_d + T_w));
    else
      PetscCall(PetscSNPrintf(f->why, sizeof(f->why),
                              "no whole wave: no row since the wave's start t_d = %.6g s", t_d));
    PetscFunctionReturn(0);
  }
  if (!isfinite(f->line.slope)) {
    PetscCall(PetscSNPrintf(f->why, sizeof(f->why),
                            "fewer than 2 rows in the %" PetscInt_FMT " whole wave(s)", f->waves));
    PetscFunctionReturn(0);
  }
  if (f->line.r2 >= r2_min || f->waves <= initial_waves) {
    f->u_F = f->line.slope;
    const char *yet = f->line.r2 >= r2_min ? "" : ": the run is not longer than the initial waves";
    char below[32] = "";
    if (!(f->line.r2 >= r2_min))
      PetscCall(PetscSNPrintf(below, sizeof(below), " < %.4g", r2_min));
    PetscCall(PetscSNPrintf(f->why, sizeof(f->why),
                            "the line over %" PetscInt_FMT " whole wave(s) (R^2 %.4g%s%s)",
                            f->waves, f->line.r2, below, yet));
  } else {
    f->u_F = f->initial.slope;
    f->from_initial = PETSC_TRUE;
    PetscCall(PetscSNPrintf(f->why, sizeof(f->why),
                            "the initial slope over %" PetscInt_FMT
                            " wave(s) (R^2 %.4g): the line over %" PetscInt_FMT
                            " waves does not fit (R^2 %.4g < %.4g)",
                            ni, f->initial.r2, f->waves, f->line.r2, r2_min));
  }
  PetscFunctionReturn(0);
}

double intestine_measures_at(const double *t, const double *y, PetscInt n, double t_at, double tol,
                             double *t_row) {
  for (PetscInt i = 0; i < n; i++)
    if (t[i] >= t_at - tol) {
      if (t_row)
        *t_row = t[i];
      return y[i];
    }
  if (t_row)
    *t_row = NAN;
  return NAN;
}

void intestine_measures_pumping(double alpha, double V_w, PetscInt n_pockets, double *u_P,
                                double *u_S, char *why, size_t why_len) {
  *u_P = *u_S = NAN;
  if (why && why_len)
    why[0] = 0;
  if (!isfinite(alpha) || !(V_w > 0) || n_pockets < 1) {
    if (why && why_len)
      snprintf(why, why_len, "alpha after one period undefined");
    return;
  }
  *u_S = alpha * V_w;
  if (alpha >= 1) {
    if (why && why_len)
      snprintf(why, why_len, "alpha = 1: all the tracked liquid left pocket 0");
    return;
  }
  *u_P = alpha / (1 - alpha) * V_w / (double)n_pockets;
}

double intestine_measures_reynolds(double b, double u, double nu) {
  if (!isfinite(u) || !(u > 0) || !(nu > 0) || !(b > 0))
    return NAN;
  return b * u / nu;
}
