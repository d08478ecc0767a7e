/* Module angle_harmonic: U = k_a (theta - theta0)^2 (doc/theory.md; LAMMPS
 * angle_style harmonic, theta0 in degrees as there). Angle arithmetic
 * (atan2 form, exact near 0 and pi) in angle_iact.h.
 * Time-step limit: a transverse displacement u of an arm of length r turns the
 * angle by u/r, so the angle acts as a spring k = U''/r^2 = 2 k_a/r^2 on it;
 * limit SPRING_DT_FACTOR sqrt(m/k) with r the shortest current arm.
 * An optional dashpot on each angle (-angle_damping, dashpot_iact.h). */
#include <math.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/events.h"
#include "dmhs/solid_modes.h"
#include "angle_iact.h"
#include "dashpot_iact.h"

typedef struct {
  double k[TOPOLOGY_MAX_TYPES];          /* [J] */
  double theta0_deg[TOPOLOGY_MAX_TYPES]; /* [deg] as given */
  double theta0[TOPOLOGY_MAX_TYPES];     /* [rad] */
  PetscInt n_k, n_theta0;
  double m_min;
  double damping; /* the dashpots' damping ratio zeta [1] */
} angle_data;

static module *angle_find(sim *s) {
  for (int m = 0; m < s->n_modules; m++)
    if (!strcmp(s->modules[m]->name, "angle_harmonic"))
      return s->modules[m];
  return NULL;
}

PetscErrorCode angle_set_default(sim *s, double k, double theta0_deg) {
  module *m = angle_find(s);
  PetscFunctionBeginUser;
  PetscCheck(m, s->comm, PETSC_ERR_ORDER,
             "angle_set_default: angle_harmonic is not enabled (call solid_modules_enable)");
  angle_data *d = m->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++) {
    d->k[t] = k;
    d->theta0_deg[t] = theta0_deg;
    d->theta0[t] = theta0_deg * M_PI / 180.0;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode angle_get_params(sim *s, double *k, double *theta0) {
  module *m = angle_find(s);
  PetscFunctionBeginUser;
  PetscCheck(m, s->comm, PETSC_ERR_ORDER, "angle_harmonic is not enabled");
  const angle_data *d = m->data;
  *k = d->k[0];
  *theta0 = d->theta0_deg[0] * M_PI / 180.0;
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_set_from_options(module *self, sim *s) {
  angle_data *d = self->data;
  PetscInt n;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL,
                    "Harmonic angles U = k_a (theta - theta0)^2 (module angle_harmonic)", NULL);
  n = TOPOLOGY_MAX_TYPES;
  PetscCall(options_read_real_array("-angle_k",
                                    "Angle stiffness k_a [J], one value or one per angle type",
                                    NULL, d->k, &n, &set));
  d->n_k = set ? n : 0;
  n = TOPOLOGY_MAX_TYPES;
  PetscCall(options_read_real_array("-angle_theta0",
                                    "Rest angle theta0 [deg], one value or one per angle type",
                                    NULL, d->theta0_deg, &n, &set));
  d->n_theta0 = set ? n : 0;
  PetscCall(options_read_real(
      "-angle_damping",
      "Damping ratio zeta of a dashpot on every angle [1] (0 = none; 0.01 lets the sub-cycled "
      "solids take a step past their fastest-mode resonance: doc/stability.md)",
      NULL, d->damping, &d->damping, NULL));
  PetscOptionsEnd();
  PetscCheck(d->damping >= 0 && d->damping < 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-angle_damping must lie in [0, 1) (got %g)", d->damping);
  /* the dashpot reads the partners' velocities */
  static const char *const reads_xv[] = {"x", "v", NULL};
  if (d->damping > 0)
    self->ghost_reads = reads_xv;
  /* the far end of an angle is two bonds from its owned anchor */
  self->reach = 0;
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->needs & MODULE_NEEDS_BONDS)
      self->reach = PetscMax(self->reach, 2.0 * s->modules[m]->reach);
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_setup(module *self, sim *s) {
  angle_data *d = self->data;
  const PetscInt nt = s->topo->n_angle_types;
  PetscFunctionBeginUser;
  PetscCall(bond_check_type_coeffs("-angle_k", d->k, d->n_k, nt));
  PetscCall(bond_check_type_coeffs("-angle_theta0", d->theta0_deg, d->n_theta0, nt));
  for (PetscInt t = 0; t < nt; t++) {
    PetscCheck(d->k[t] >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-angle_k must be >= 0 (type %" PetscInt_FMT ": %g J)", t, d->k[t]);
    PetscCheck(d->theta0_deg[t] >= 0 && d->theta0_deg[t] <= 180, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-angle_theta0 must lie in [0, 180] deg (type %" PetscInt_FMT ": %g)", t,
               d->theta0_deg[t]);
  }
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++)
    d->theta0[t] = d->theta0_deg[t] * M_PI / 180.0;
  PetscCall(bond_min_solid_mass(s, &d->m_min));
  PetscFunctionReturn(0);
}

/* One pass over the angles, tallying what is asked (the LAMMPS ev_tally idea): forces into a;
 * the three-body virial -(a (x) F_i + b (x) F_k) (a = x_i - x_j, b = x_k - x_j), a third to
 * each of the three rows as LAMMPS' compute stress/atom does, into W; the weighted energy
 * into *e. force, virial, energy are constants at each call below, so each use compiles to
 * its own loop. */
static inline void angle_tally(const angle_data *d, const sim *s, int force, int virial, int energy,
                               double (*restrict W)[3], double *e) {
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  const PetscInt na = t->n_angle_local;
  const PetscInt(*restrict angle)[3] = (const PetscInt(*)[3])t->angle;
  const PetscInt *restrict type = t->angle_ltype;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double(*restrict v)[2] = (const double(*)[2])ps->v;
  const double *restrict mass = ps->mass;
  const double *restrict K = d->k, *restrict TH0 = d->theta0;
  const double zeta = d->damping;
  double(*restrict a)[2] = ps->a;
  double local = 0;
  for (PetscInt q = 0; q < na; q++) {
    const PetscInt i = angle[q][0], j = angle[q][1], k = angle[q][2], ty = type[q];
    const double ra[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double rb[2] = {x[k][0] - x[j][0], x[k][1] - x[j][1]};
    double fi[2], fk[2];
    const double u = angle_harmonic_iact(K[ty], TH0[ty], ra, rb, fi, fk);
    if (zeta > 0 && (force || virial)) {
      const double va[2] = {v[i][0] - v[j][0], v[i][1] - v[j][1]};
      const double vb[2] = {v[k][0] - v[j][0], v[k][1] - v[j][1]};
      angle_dashpot_iact(zeta, 2.0 * K[ty], mass[i], mass[j], mass[k], ra, rb, va, vb, fi, fk);
    }
    if (force) {
      const double mi = 1.0 / mass[i], mj = 1.0 / mass[j], mk = 1.0 / mass[k];
      a[i][0] += fi[0] * mi;
      a[i][1] += fi[1] * mi;
      a[k][0] += fk[0] * mk;
      a[k][1] += fk[1] * mk;
      a[j][0] -= (fi[0] + fk[0]) * mj;
      a[j][1] -= (fi[1] + fk[1]) * mj;
    }
    if (virial) {
      const double third = -1.0 / 3.0;
      const double w[3] = {third * (ra[0] * fi[0] + rb[0] * fk[0]),
                           third * (ra[0] * fi[1] + rb[0] * fk[1]),
                           third * (ra[1] * fi[1] + rb[1] * fk[1])};
      for (int c = 0; c < 3; c++) {
        W[i][c] += w[c];
        W[j][c] += w[c];
        W[k][c] += w[c];
      }
    }
    if (energy)
      local += t->angle_weight[q] * u;
  }
  if (energy)
    *e = local;
}

static PetscErrorCode angle_compute(module *self, sim *s) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.angle, 0, 0, 0, 0));
  angle_tally(self->data, s, 1, 0, 0, NULL, NULL);
  PetscCall(PetscLogFlops(60.0 * (double)s->topo->n_angle_local));
  PetscCall(PetscLogEventEnd(events.angle, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_virial(module *self, sim *s, double (*W)[3]) {
  PetscFunctionBeginUser;
  angle_tally(self->data, s, 0, 1, 0, W, NULL);
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_energy_sum(module *self, sim *s, double *e) {
  double local = 0;
  PetscFunctionBeginUser;
  angle_tally(self->data, s, 0, 0, 1, NULL, &local);
  PetscCallMPI(MPI_Allreduce(&local, e, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_max_dt(module *self, sim *s, dt_limits *l) {
  const angle_data *d = self->data;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  double local = INFINITY, limit;
  PetscFunctionBeginUser;
  if (!isfinite(d->m_min))
    PetscFunctionReturn(0);
  PetscCall(bond_check_resolved(s, "angle time-step limit"));
  /* evaluated before every step: the smallest r^2/k over the angles, one root at the end
   * (a root per angle was 6 % of a membrane scene's step) */
  double r2_over_k = INFINITY;
  for (PetscInt q = 0; q < t->n_angle_local; q++) {
    const PetscInt i = t->angle[q][0], j = t->angle[q][1], k = t->angle[q][2],
                   ty = t->angle_ltype[q];
    if (!(d->k[ty] > 0))
      continue;
    const double dij[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double dkj[2] = {ps->x[k][0] - ps->x[j][0], ps->x[k][1] - ps->x[j][1]};
    const double r2 =
        PetscMin(dij[0] * dij[0] + dij[1] * dij[1], dkj[0] * dkj[0] + dkj[1] * dkj[1]);
    r2_over_k = PetscMin(r2_over_k, r2 / d->k[ty]);
  }
  if (isfinite(r2_over_k))
    local = SPRING_DT_FACTOR * sqrt(d->m_min * r2_over_k / 2.0);
  PetscCallMPI(MPI_Allreduce(&local, &limit, 1, MPI_DOUBLE, MPI_MIN, s->comm));
  if (isfinite(limit))
    PetscCall(dt_limits_add(l, "angle harmonic", "0.2 sqrt(m/k), k = 2 k_a/r^2, r = shortest arm",
                            limit));
  PetscFunctionReturn(0);
}

/* Jacobian blocks (module.h): U'' grad(theta) grad(theta)^T = 2 k_a g_p g_q^T, with
 * g_i = (a_y, -a_x)/|a|^2, g_k = (-b_y, b_x)/|b|^2, g_j = -(g_i + g_k) (up to one sign,
 * which the products lose). The curvature term U' grad^2(theta) is left out: it
 * vanishes at rest, and the angles stay near it. */
static PetscErrorCode angle_jacobian(module *self, sim *s, solid_jacobian *J) {
  const angle_data *d = self->data;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < t->n_angle_local; q++) {
    const PetscInt r[3] = {t->angle[q][0], t->angle[q][1], t->angle[q][2]};
    const double ka = d->k[t->angle_ltype[q]];
    const double a[2] = {ps->x[r[0]][0] - ps->x[r[1]][0], ps->x[r[0]][1] - ps->x[r[1]][1]};
    const double b[2] = {ps->x[r[2]][0] - ps->x[r[1]][0], ps->x[r[2]][1] - ps->x[r[1]][1]};
    const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1];
    if (!(ka > 0) || !(a2 > 0) || !(b2 > 0))
      continue;
    double g[3][2] = {{a[1] / a2, -a[0] / a2}, {0, 0}, {-b[1] / b2, b[0] / b2}};
    g[1][0] = -(g[0][0] + g[2][0]);
    g[1][1] = -(g[0][1] + g[2][1]);
    for (int u = 0; u < 3; u++)
      for (int v = 0; v < 3; v++) {
        const double B[2][2] = {{2.0 * ka * g[u][0] * g[v][0], 2.0 * ka * g[u][0] * g[v][1]},
                                {2.0 * ka * g[u][1] * g[v][0], 2.0 * ka * g[u][1] * g[v][1]}};
        PetscCall(solid_jacobian_add(J, r[u], r[v], B));
      }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_view(module *self, sim *s, PetscViewer v) {
  const angle_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(
      v, "angle_harmonic: %" PetscInt64_FMT " angles, U = k_a (theta - theta0)^2\n",
      s->topo->n_angles_global));
  for (PetscInt t = 0; t < s->topo->n_angle_types; t++)
    PetscCall(
        PetscViewerASCIIPrintf(v, "  angle type %" PetscInt_FMT ": k_a = %g J, theta0 = %g deg\n",
                               t, d->k[t], d->theta0_deg[t]));
  if (d->damping > 0)
    PetscCall(
        PetscViewerASCIIPrintf(v, "  dashpots on the angles: damping ratio %g\n", d->damping));
  PetscFunctionReturn(0);
}

static PetscErrorCode angle_destroy(module *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode angle_harmonic_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "angle_harmonic";
  static const char *const reads[] = {"x", NULL}; /* ghost positions */
  (*m)->ghost_reads = reads;
  (*m)->solid_internal = PETSC_TRUE;
  (*m)->needs = MODULE_NEEDS_ANGLES;
  (*m)->set_from_options = angle_set_from_options;
  (*m)->setup = angle_setup;
  (*m)->compute = angle_compute;
  (*m)->max_dt = angle_max_dt;
  (*m)->jacobian_blocks = angle_jacobian;
  (*m)->view = angle_view;
  (*m)->destroy = angle_destroy;
  (*m)->energy = angle_energy_sum;
  (*m)->virial = angle_virial;
  PetscCall(PetscNew((angle_data **)&(*m)->data));
  /* the vein leaflets' angles (doc/cases.md) */
  angle_data *d = (*m)->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++) {
    d->k[t] = 0.01;
    d->theta0_deg[t] = 90.0;
    d->theta0[t] = M_PI / 2;
  }
  PetscFunctionReturn(0);
}
