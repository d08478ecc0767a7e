/* Velocity Verlet, kick-drift-kick, for positions, velocities and (with the
 * continuity equation) densities, as LAMMPS' fix sph does:
 *   v_est  = v^n + dt a^n                  (predicted velocity for the viscous
 *                                           and continuity terms at t^{n+1})
 *   v      = v^n + dt/2 a^n,  rho = rho^n + dt/2 drho^n
 *   x^{n+1} = x^n + dt v
 *   forces at x^{n+1} -> a^{n+1}, drho^{n+1}
 *   v^{n+1} = v + dt/2 a^{n+1},  rho^{n+1} = rho + dt/2 drho^{n+1}
 * Walls move with their prescribed velocity and are not kicked.
 * Also: the per-step state check (no NaN ever reaches an output file). */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/integrate.h"
#include "dmhs/events.h"
#include "dmhs/substep.h"

/* The density the force evaluation sees, on every row but walls: rho^n + dt/2 drho^n (the
 * kick's), or
 * with -sph_density_predict rho^n + dt drho^n, whose drho^n the second half
 * takes back for the trapezoid rho^n + dt/2 (drho^n + drho^{n+1}). The
 * half-step density lags the drifted positions by dt/2, and a pressure
 * oscillation of frequency omega then grows at omega^2 dt/4 (doc/theory.md). */
static void integrate_density_first(particles *ps, double dt, int predict) {
  const PetscInt *restrict type = ps->type;
  double *restrict rho = ps->rho, *restrict prev = ps->drho_prev;
  const double *restrict drho = ps->drho;
  if (predict)
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      const int on = type[i] != PTYPE_WALL;
      prev[i] = on ? drho[i] : prev[i];
      rho[i] = on ? rho[i] + dt * drho[i] : rho[i];
    }
  else
    for (PetscInt i = 0; i < ps->n_owned; i++)
      rho[i] = type[i] != PTYPE_WALL ? rho[i] + 0.5 * dt * drho[i] : rho[i];
}

/* What the enabled modules declare they integrate: density rates (continuity), and
 * whether their forces see the predicted density. */
static void integrate_density_mode(const sim *s, int *continuity, int *predict) {
  unsigned needs = 0;
  for (int m = 0; m < s->n_modules; m++)
    needs |= s->modules[m]->needs;
  *continuity = (needs & MODULE_INTEGRATES_DENSITY) != 0;
  *predict = *continuity && (needs & MODULE_PREDICTS_DENSITY) != 0;
}

/* The first kick and the drift over the rows' components; subcycled (a constant) freezes the
 * rows marked substepped (the solids, and the liquid in a sub-cycled contact: their motion
 * belongs to the sub-steps). Selects instead of branches, so that the loop vectorises: a wall
 * keeps its prescribed velocity (v_est = v) and drifts; a frozen row keeps x, v and v_est (its
 * density belongs to the liquid's step). */
static inline void integrate_kick_drift(particles *ps, double dt, double half, int subcycled) {
  const PetscInt *restrict type = ps->type, *restrict sub = ps->substepped;
  double *restrict x = &ps->x[0][0], *restrict v = &ps->v[0][0], *restrict v_est = &ps->v_est[0][0];
  const double *restrict a = &ps->a[0][0];
  for (PetscInt j = 0; j < DMHS_DIM * ps->n_owned; j++) { /* j: row j / DMHS_DIM, component */
    const PetscInt t = type[j / DMHS_DIM];
    const int wall = t == PTYPE_WALL, frozen = subcycled ? sub[j / DMHS_DIM] != 0 : 0;
    const double vj = v[j], v_new = wall || frozen ? vj : vj + half * a[j];
    const double est = wall ? vj : vj + dt * a[j];
    v_est[j] = frozen ? v_est[j] : est;
    v[j] = v_new;
    x[j] = frozen ? x[j] : x[j] + dt * v_new;
  }
}

PetscErrorCode integrate_first_half(sim *s) {
  particles *ps = &s->ps;
  const double dt = s->dt, half = 0.5 * s->dt;
  int continuity, predict;
  integrate_density_mode(s, &continuity, &predict);
  const int subcycled = s->substeps.on; /* marked rows move in substep_solids */
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.integrate, 0, 0, 0, 0));
  if (subcycled)
    integrate_kick_drift(ps, dt, half, 1);
  else /* nothing frozen: the loop neither reads v_est nor keeps x */
    integrate_kick_drift(ps, dt, half, 0);
  if (continuity) /* walls' densities are the wall pass's (sph_wall.c) */
    integrate_density_first(ps, dt, predict);
  PetscCall(PetscLogEventEnd(events.integrate, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* 1 when x is an infinity or a NaN: the exponent bits all set, tested as integers so that the
 * scans below have no branch per value */
static inline unsigned not_finite(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof(u));
  return (u & 0x7ff0000000000000ULL) == 0x7ff0000000000000ULL;
}

/* The second kick over the rows' components: v += h a, h = dt/2 (with subcycled, a constant, a
 * row that moved on the sub-steps: the last sub-step's dt/2 n_sub), walls untouched; selects
 * instead of branches, so that the loop vectorises. With check (a constant), also the state
 * check's test of x, v and a on what it leaves (integrate_state_ok), while the values are at
 * hand; returns nonzero on a bad one. */
static inline unsigned integrate_kick_components(const sim *s, double half, double half_solid,
                                                 int subcycled, int check) {
  const particles *ps = &s->ps;
  const PetscInt *restrict type = ps->type, *restrict sub = ps->substepped;
  const double *restrict x = &ps->x[0][0], *restrict a = &ps->a[0][0];
  /* respa: the forces not sub-cycled (a_hold) kick a row that moved on the sub-steps over
   * dt/2 here, half_solid of it with the rest of a */
  const double *restrict a_hold = subcycled ? &ps->a_hold[0][0] : NULL;
  const double rest = subcycled && s->substeps.respa ? half - half_solid : 0.0;
  double *restrict v = &ps->v[0][0];
  double lo[DMHS_DIM], hi[DMHS_DIM];
  for (int k = 0; k < DMHS_DIM; k++) { /* periodic directions wrap at the next build */
    lo[k] = s->dom.periodic[k] ? -INFINITY : s->dom.lo[k];
    hi[k] = s->dom.periodic[k] ? INFINITY : s->dom.hi[k];
  }
  const double lo0 = lo[0], lo1 = lo[1], hi0 = hi[0], hi1 = hi[1];
  unsigned bad = 0;
  for (PetscInt j = 0; j < DMHS_DIM * ps->n_owned; j++) { /* j: row j / DMHS_DIM, component */
    const PetscInt t = type[j / DMHS_DIM];
    const int moved = subcycled && sub[j / DMHS_DIM];
    const double h = moved ? half_solid : half;
    const double vj = v[j], aj = a[j];
    double v_new = t == PTYPE_WALL ? vj : vj + h * aj;
    if (subcycled)
      v_new = moved && rest != 0.0 ? v_new + rest * a_hold[j] : v_new;
    v[j] = v_new;
    if (check) {
      const double xj = x[j];
      const double lo_j = j % DMHS_DIM ? lo1 : lo0, hi_j = j % DMHS_DIM ? hi1 : hi0;
      bad |= not_finite(xj) | not_finite(v_new) | not_finite(aj) | (xj < lo_j) | (xj > hi_j);
    }
  }
  return bad;
}

/* The second half of the density (density, a constant: 0 none, 1 the half step, 2 the
 * predicted density's trapezoid, integrate_density_first), walls untouched; with check,
 * also the state check's test of rho, p and drho. */
static inline unsigned integrate_density_rows(const particles *ps, double dt, int density,
                                              int check) {
  const PetscInt *restrict type = ps->type;
  const double *restrict p = ps->p, *restrict drho = ps->drho, *restrict prev = ps->drho_prev;
  double *restrict rho = ps->rho;
  unsigned bad = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const double r = rho[i], rate = drho[i];
    double r_new = r;
    if (density == 1)
      r_new = type[i] != PTYPE_WALL ? r + 0.5 * dt * rate : r;
    else if (density == 2)
      r_new = type[i] != PTYPE_WALL ? r + 0.5 * dt * (rate - prev[i]) : r;
    rho[i] = r_new;
    if (check)
      bad |= not_finite(r_new) | not_finite(p[i]) | not_finite(rate) | (r_new <= 0);
  }
  return bad;
}

PetscErrorCode integrate_second_half(sim *s) {
  particles *ps = &s->ps;
  const double half = 0.5 * s->dt;
  int continuity, predict;
  integrate_density_mode(s, &continuity, &predict);
  /* sub-cycled solids: the second half kick of their last sub-step */
  const double half_solid = s->substeps.on ? half / (double)s->substeps.n : half;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.integrate, 0, 0, 0, 0));
  if (s->substeps.on)
    (void)integrate_kick_components(s, half, half_solid, 1, 0);
  else
    (void)integrate_kick_components(s, half, half_solid, 0, 0);
  if (continuity)
    (void)integrate_density_rows(ps, s->dt, predict ? 2 : 1, 0);
  PetscCall(PetscLogEventEnd(events.integrate, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* One branch-free pass over the owned rows; only a run that has gone wrong pays for the
 * search below that names the particle and the quantity. */
static PetscBool integrate_state_ok(const sim *s) {
  const particles *ps = &s->ps;
  double lo[DMHS_DIM], hi[DMHS_DIM];
  for (int k = 0; k < DMHS_DIM; k++) { /* periodic directions wrap at the next build */
    lo[k] = s->dom.periodic[k] ? -INFINITY : s->dom.lo[k];
    hi[k] = s->dom.periodic[k] ? INFINITY : s->dom.hi[k];
  }
  unsigned bad = 0;
  if (ps->p && ps->drho) /* with SPH: one pass over everything */
    for (PetscInt i = 0; i < ps->n_owned; i++)
      bad |= not_finite(ps->x[i][0]) | not_finite(ps->x[i][1]) | not_finite(ps->v[i][0]) |
             not_finite(ps->v[i][1]) | not_finite(ps->rho[i]) | not_finite(ps->p[i]) |
             not_finite(ps->a[i][0]) | not_finite(ps->a[i][1]) | not_finite(ps->drho[i]) |
             (ps->rho[i] <= 0) | (ps->x[i][0] < lo[0]) | (ps->x[i][0] > hi[0]) |
             (ps->x[i][1] < lo[1]) | (ps->x[i][1] > hi[1]);
  else
    for (PetscInt i = 0; i < ps->n_owned; i++)
      bad |= not_finite(ps->x[i][0]) | not_finite(ps->x[i][1]) | not_finite(ps->v[i][0]) |
             not_finite(ps->v[i][1]) | not_finite(ps->rho[i]) | not_finite(ps->a[i][0]) |
             not_finite(ps->a[i][1]) | (ps->p && not_finite(ps->p[i])) |
             (ps->drho && not_finite(ps->drho[i])) | (ps->rho[i] <= 0) | (ps->x[i][0] < lo[0]) |
             (ps->x[i][0] > hi[0]) | (ps->x[i][1] < lo[1]) | (ps->x[i][1] > hi[1]);
  return bad ? PETSC_FALSE : PETSC_TRUE;
}

/* With SPH's fields, two passes over the rows instead of the three of integrate_second_half
 * and integrate_check_state: the same operations and the same test. */
PetscErrorCode integrate_second_half_checked(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  if (!ps->p || !ps->drho) { /* without SPH: the two passes */
    PetscCall(integrate_second_half(s));
    PetscCall(integrate_check_state(s));
    PetscFunctionReturn(0);
  }
  const double half = 0.5 * s->dt;
  const double half_solid = s->substeps.on ? half / (double)s->substeps.n : half;
  int continuity, predict;
  integrate_density_mode(s, &continuity, &predict);
  PetscCall(PetscLogEventBegin(events.integrate, 0, 0, 0, 0));
  unsigned bad = s->substeps.on ? integrate_kick_components(s, half, half_solid, 1, 1)
                                : integrate_kick_components(s, half, half_solid, 0, 1);
  if (!continuity) /* each density mode its own loop */
    bad |= integrate_density_rows(ps, s->dt, 0, 1);
  else if (!predict)
    bad |= integrate_density_rows(ps, s->dt, 1, 1);
  else
    bad |= integrate_density_rows(ps, s->dt, 2, 1);
  PetscCall(PetscLogEventEnd(events.integrate, 0, 0, 0, 0));
  if (bad) /* the check's own search names the particle and stops the run */
    PetscCall(integrate_check_state(s));
  PetscFunctionReturn(0);
}

PetscErrorCode integrate_check_state(sim *s) {
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.check_state, 0, 0, 0, 0));
  const PetscInt n_check = integrate_state_ok(s) ? 0 : ps->n_owned;
  for (PetscInt i = 0; i < n_check; i++) {
    const char *bad = NULL;
    if (!isfinite(ps->x[i][0]) || !isfinite(ps->x[i][1]))
      bad = "position";
    else if (!isfinite(ps->v[i][0]) || !isfinite(ps->v[i][1]))
      bad = "velocity";
    else if (!isfinite(ps->rho[i]) || ps->rho[i] <= 0)
      bad = "density";
    else if (ps->p && !isfinite(ps->p[i]))
      bad = "pressure";
    else if (!isfinite(ps->a[i][0]) || !isfinite(ps->a[i][1]))
      bad = "acceleration";
    else if (ps->drho && !isfinite(ps->drho[i]))
      bad = "density rate";
    PetscCheck(
        bad || domain_contains(&s->dom, ps->x[i]), PETSC_COMM_SELF, PETSC_ERR_FP,
        "particle gid %" PetscInt64_FMT " escaped the domain at step %" PetscInt_FMT
        ", t = %g s: x = (%g, %g) outside [%g, %g] x [%g, %g]; the run is unstable or a wall leaks "
        "(try a smaller -dt)",
        ps->gid[i], s->step, s->t, ps->x[i][0], ps->x[i][1], s->dom.lo[0], s->dom.hi[0],
        s->dom.lo[1], s->dom.hi[1]);
    PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_FP,
               "run blew up at step %" PetscInt_FMT ", t = %g s: particle gid %" PetscInt64_FMT
               " (type %" PetscInt_FMT
               ") has a non-finite or invalid %s (x = %g %g, v = %g %g, a = %g %g, "
               "rho = %g, drho/dt = %g); try a smaller -dt (see the stability report)",
               s->step, s->t, ps->gid[i], ps->type[i], bad, ps->x[i][0], ps->x[i][1], ps->v[i][0],
               ps->v[i][1], ps->a[i][0], ps->a[i][1], ps->rho[i], ps->drho ? ps->drho[i] : 0.0);
  }
  PetscCall(PetscLogEventEnd(events.check_state, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
