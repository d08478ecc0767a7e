/* The colon's measures from the rows of intestine.csv (src/scenes/intestine/intestine_measures.c,
 * doc/theory.md, "Peristalsis and tracking"): the front velocity u_F as the
 * thesis defines it, alpha after one period and at the last whole wave's end,
 * the pouring and surfing velocities u_P and u_S, and the Reynolds numbers.
 * Plain functions of arrays (no solver state), so that each definition has one
 * implementation, used by the end-of-run summary and tested on its own
 * (test/unit/test_intestine_measures.c). An undefined value is NAN, with the
 * reason in a short text (no commas: it goes into a CSV cell). */
#ifndef DMHS_INTESTINE_MEASURES_H
#define DMHS_INTESTINE_MEASURES_H
#include <petscsys.h>

/* x(t) ~ x0 + slope (t - t0) over the rows with t in [t0, t1]: least squares,
 * r2 = 1 - SS_res/SS_tot (1 when x is constant over the window). slope, x0 and
 * r2 are NAN when fewer than 2 rows lie in the window. */
typedef struct {
  double t0, t1;        /* the window [s] */
  double slope, x0, r2; /* [m/s], [m] (the line at t0), [1] */
  PetscInt n;           /* rows fitted */
} intestine_line;

/* The front velocity: the least-squares line of x_F over the run's whole waves
 * ([t_d, t_d + waves T_w]); where that line does not fit (r2 < r2_min) and the
 * run is longer than initial_waves, the initial slope, the line over the first
 * initial_waves waves. */
typedef struct {
  PetscInt waves;            /* whole waves in the rows (capped by the schedule's waves) */
  intestine_line line;       /* over the whole waves */
  intestine_line initial;    /* over the first min(waves, initial_waves) whole waves */
  intestine_line first_wave; /* over [t_d, t_d + T_w] */
  double u_F;                /* line.slope or initial.slope; NAN with no whole wave */
  PetscBool from_initial;    /* u_F is the initial slope */
  char why[160];             /* how u_F was chosen, or why it is undefined */
} intestine_front;

/* tol [s] below: a row within tol of an instant (t_d, t_d + k T_w) counts as
 * written at it. The solver writes a row at the first step with t >= the output
 * time - dt/2, so dt is a safe tol. */

/* Whole waves between t_d and t_last: floor((t_last - t_d + tol)/T_w), >= 0,
 * capped by waves_max when > 0. */
PetscInt intestine_measures_whole_waves(double t_last, double t_d, double T_w, PetscInt waves_max,
                                        double tol);
/* Least squares of x(t) over the rows with t0 - tol <= t <= t1 + tol. */
PetscErrorCode intestine_measures_line(const double *t, const double *x, PetscInt n, double t0,
                                       double t1, double tol, intestine_line *line);
/* u_F and its three lines from the rows (t, x_F); the rows must be in time order.
 * waves_max: the schedule's number of waves (0: unlimited); initial_waves >= 1;
 * 0 < r2_min <= 1. */
PetscErrorCode intestine_measures_front(const double *t, const double *x, PetscInt n, double t_d,
                                        double T_w, PetscInt waves_max, PetscInt initial_waves,
                                        double r2_min, double tol, intestine_front *f);
/* The value of y in the first row with t >= t_at - tol (*t_row its time); NAN
 * (and *t_row NAN) when no row reaches t_at. */
double intestine_measures_at(const double *t, const double *y, PetscInt n, double t_at, double tol,
                             double *t_row);
/* u_P = alpha/(1 - alpha) V_w/(N+1) (pouring) and u_S = alpha V_w (surfing):
 * NAN when alpha is NAN; u_P also when alpha >= 1 (every tracked particle left:
 * the pouring series diverges). why (size >= 96) says which, "" otherwise. */
void intestine_measures_pumping(double alpha, double V_w, PetscInt n_pockets, double *u_P,
                                double *u_S, char *why, size_t why_len);
/* Re = b u/nu, for u > 0 only: NAN when u is NAN or u <= 0 (a front that did not
 * advance has no Reynolds number; its u_F is reported as measured). */
double intestine_measures_reynolds(double b, double u, double nu);

#endif
