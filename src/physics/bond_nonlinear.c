/* Module bond_nonlinear: U = k_b x^2/(r_max^2 - x^2), x = r - r0 (doc/theory.md; LAMMPS
 * bond_style nonlinear), k_b [J], r0 [m], r_max [m] per bond type (-bond_k,
 * -bond_r0, -bond_rmax). Pair arithmetic in bond_iact.h.
 *
 * Guards LAMMPS does not have: a bond with |x| >= r_max stops the run naming
 * both particles, the step and the stretch (past r_max the force changes sign
 * and the structure flies apart); a warning is printed once when a bond
 * passes 0.95 r_max. The bond stiffens as it stretches,
 *   k_eff = U'' = 2 k_b r_max^2 (r_max^2 + 3x^2)/(r_max^2 - x^2)^3,
 * so its time-step limit SPRING_DT_FACTOR sqrt(m/k_eff) is evaluated at the
 * largest current stretch, in the pre-flight report and again after every
 * sweep (stop or warn per -preflight when dt exceeds it). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/bond.h"
#include "dmhs/events.h"
#include "dmhs/solid_modes.h"
#include "bond_iact.h"
#include "virial_iact.h"

typedef struct {
  bond_params p; /* first: bond_set_default writes through it */
  PetscBool warned_stretch;
} bond_nonlinear_data;

static PetscErrorCode bond_nonlinear_set_from_options(module *self, sim *s) {
  bond_params *p = self->data;
  PetscInt n;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL,
                    "Nonlinear bonds U = k_b (r-r0)^2/(r_max^2-(r-r0)^2) (module bond_nonlinear)",
                    NULL);
  PetscCall(bond_options_k_r0(PetscOptionsObject, p,
                              "Bond energy scale k_b [J], one value or one per bond type"));
  n = TOPOLOGY_MAX_TYPES;
  PetscCall(options_read_real_array("-bond_rmax",
                                    "Largest stretch |r - r0| = r_max [m] (the run stops there)",
                                    NULL, p->rmax, &n, &set));
  p->n_rmax = set ? n : 0;
  PetscOptionsEnd();
  double reach = 0;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++)
    reach = PetscMax(reach, p->r0[t] + p->rmax[t]);
  self->reach = reach; /* the longest a bond can be */
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_nonlinear_setup(module *self, sim *s) {
  bond_params *p = self->data;
  const PetscInt nt = s->topo->n_bond_types;
  PetscFunctionBeginUser;
  PetscCall(bond_claim_scene_types(s, self));
  PetscCall(bond_setup_k_r0(s, p, "J"));
  PetscCall(bond_check_type_coeffs("-bond_rmax", p->rmax, p->n_rmax, nt));
  for (PetscInt t = 0; t < nt; t++)
    PetscCheck(p->rmax[t] > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-bond_rmax must be > 0 (type %" PetscInt_FMT ": %g m)", t, p->rmax[t]);
  PetscFunctionReturn(0);
}

/* Largest |x|/r_max over the local bonds, and which bond entry. */
static double bond_nonlinear_max_stretch(const module *self, const bond_params *p,
                                         const topology *t, const particles *ps, PetscInt *which) {
  double best = 0;
  *which = -1;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    const PetscInt i = t->bond[b][0], j = t->bond[b][1], ty = t->bond_ltype[b];
    if (t->bond_owner[ty] != self)
      continue;
    const double r = hypot(ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]);
    const double f = fabs(r - p->r0[ty]) / p->rmax[ty];
    if (f > best) {
      best = f;
      *which = b;
    }
  }
  return best;
}

/* The spring limit at stretch fraction f (of r_max) for type ty. */
static double bond_nonlinear_limit(const bond_params *p, PetscInt ty, double f) {
  const double k = bond_nonlinear_stiffness(p->k[ty], p->rmax[ty], f * p->rmax[ty]);
  return SPRING_DT_FACTOR * sqrt(p->m_min / k);
}

/* One pass over the module's bonds, tallying what is asked (the LAMMPS ev_tally idea): forces
 * into a, with the largest |x|/r_max and its bond entry in *worst, *worst_b; the pair virial
 * into W (both ends get -1/2 d (x) F_i, F_i = fr d); the weighted energy into *e. force,
 * virial, energy are constants at each call below, so each use compiles to its own loop. */
static inline void nonlinear_tally(const module *self, const sim *s, int force, int virial,
                                   int energy, double *worst, PetscInt *worst_b,
                                   double (*restrict W)[3], double *e) {
  const bond_params *p = self->data;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  const PetscInt nb = t->n_bond_local;
  const PetscInt(*restrict bond)[2] = (const PetscInt(*)[2])t->bond;
  const PetscInt *restrict type = t->bond_ltype;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double *restrict mass = ps->mass;
  const double *restrict K = p->k, *restrict R0 = p->r0, *restrict L = p->rmax;
  double(*restrict a)[2] = ps->a;
  const void *const *restrict owner = t->bond_owner;
  double big = 0, local = 0;
  PetscInt big_b = -1;
  for (PetscInt b = 0; b < nb; b++) {
    const PetscInt i = bond[b][0], j = bond[b][1], ty = type[b];
    if (owner[ty] != self) /* another module's bond type */
      continue;
    const double dd[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double r = sqrt(dd[0] * dd[0] + dd[1] * dd[1]);
    if (force) {
      const double f = fabs(r - R0[ty]) / L[ty];
      if (f > big) { /* rare: no PETSc call in the loop, the check follows it */
        big = f;
        big_b = b;
      }
    }
    if (force || virial) {
      const double fr = bond_nonlinear_iact(K[ty], R0[ty], L[ty], r);
      bond_pair_apply(a, W, mass, i, j, fr, dd, force, virial);
    }
    if (energy)
      local += t->bond_weight[b] * bond_nonlinear_energy(K[ty], R0[ty], L[ty], r);
  }
  if (force) {
    *worst = big;
    *worst_b = big_b;
  }
  if (energy)
    *e = local;
}

static PetscErrorCode bond_nonlinear_compute(module *self, sim *s) {
  bond_nonlinear_data *d = self->data;
  const bond_params *p = &d->p;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  double worst = 0; /* largest |x|/r_max */
  PetscInt worst_b = -1;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.bond, 0, 0, 0, 0));
  nonlinear_tally(self, s, 1, 0, 0, &worst, &worst_b, NULL, NULL);
  PetscCall(PetscLogFlops(30.0 * (double)t->n_bond_local));
  PetscCall(PetscLogEventEnd(events.bond, 0, 0, 0, 0));
  if (worst_b < 0)
    PetscFunctionReturn(0);
  const PetscInt i = t->bond[worst_b][0], j = t->bond[worst_b][1], ty = t->bond_ltype[worst_b];
  const double r = hypot(ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]);
  PetscCheck(worst < 1.0, PETSC_COMM_SELF, PETSC_ERR_FP,
             "nonlinear bond between particles gid %" PetscInt64_FMT " and gid %" PetscInt64_FMT
             " broke at step %" PetscInt_FMT
             ", t = %g s: |r - r0| = %g m >= r_max = %g m (r = %g m, r0 = %g m, "
             "stretch %.3f r_max); past r_max the force changes sign. Lower -dt or the load, or "
             "raise -bond_rmax / -bond_k",
             ps->gid[i], ps->gid[j], s->step, s->t, fabs(r - p->r0[ty]), p->rmax[ty], r, p->r0[ty],
             worst);
  if (worst >= 0.95 && !d->warned_stretch) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "WARNING: nonlinear bond gid %" PetscInt64_FMT "-%" PetscInt64_FMT
                          " stretched to %.3f r_max at step %" PetscInt_FMT
                          ", t = %g s (the run stops at r_max; "
                          "this warning is printed once)\n",
                          ps->gid[i], ps->gid[j], worst, s->step, s->t));
    d->warned_stretch = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_nonlinear_energy_sum(module *self, sim *s, double *e) {
  double local = 0;
  PetscFunctionBeginUser;
  nonlinear_tally(self, s, 0, 0, 1, NULL, NULL, NULL, &local);
  PetscCallMPI(MPI_Allreduce(&local, e, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_nonlinear_virial(module *self, sim *s, double (*W)[3]) {
  PetscFunctionBeginUser;
  nonlinear_tally(self, s, 0, 1, 0, NULL, NULL, W, NULL);
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_nonlinear_max_dt(module *self, sim *s, dt_limits *l) {
  const bond_params *p = self->data;
  double local = INFINITY, limit, f_local = 0, f;
  PetscInt which;
  PetscFunctionBeginUser;
  if (!isfinite(p->m_min))
    PetscFunctionReturn(0);
  PetscCall(bond_check_resolved(s, "bond nonlinear time-step limit"));
  /* per type, at that type's largest current stretch (rest when it has none here) */
  for (PetscInt ty = 0; ty < s->topo->n_bond_types; ty++)
    local = PetscMin(local, bond_nonlinear_limit(p, ty, 0.0));
  f_local = bond_nonlinear_max_stretch(self, p, s->topo, &s->ps, &which);
  if (which >= 0)
    local = PetscMin(local, bond_nonlinear_limit(p, s->topo->bond_ltype[which], f_local));
  PetscCallMPI(MPI_Allreduce(&local, &limit, 1, MPI_DOUBLE, MPI_MIN, s->comm));
  PetscCallMPI(MPI_Allreduce(&f_local, &f, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  char formula[96];
  PetscCall(PetscSNPrintf(formula, sizeof(formula),
                          "0.2 sqrt(m/k_eff), k_eff = U'' at max stretch %.2f r_max", f));
  PetscCall(dt_limits_add(l, "bond nonlinear", formula, limit));
  PetscFunctionReturn(0);
}

/* Jacobian blocks (module.h): U'' along the bond and U'/r across, at its stretch. */
static PetscErrorCode bond_nonlinear_jacobian(module *self, sim *s, solid_jacobian *J) {
  const bond_params *p = self->data;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    const PetscInt i = t->bond[b][0], j = t->bond[b][1], ty = t->bond_ltype[b];
    if (t->bond_owner[ty] != self)
      continue;
    const double d[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double r = sqrt(d[0] * d[0] + d[1] * d[1]), x = r - p->r0[ty];
    if (!(fabs(x) < p->rmax[ty])) /* broken: the force sweep stops the run */
      continue;
    PetscCall(bond_jacobian_add(J, i, j, d, r, bond_nonlinear_stiffness(p->k[ty], p->rmax[ty], x),
                                bond_nonlinear_iact(p->k[ty], p->r0[ty], p->rmax[ty], r)));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_nonlinear_view(module *self, sim *s, PetscViewer v) {
  const bond_params *p = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(
      v,
      "bond_nonlinear: %" PetscInt64_FMT " bonds, U = k_b x^2/(r_max^2 - x^2); warn at 0.95 "
      "r_max, stop at r_max; 1-2/1-3 partners %s pair sums\n",
      s->topo->n_bonds_global, s->topo->special_include ? "included in" : "excluded from"));
  for (PetscInt t = 0; t < s->topo->n_bond_types; t++)
    PetscCall(PetscViewerASCIIPrintf(
        v, "  bond type %" PetscInt_FMT ": k_b = %g J, r0 = %g m, r_max = %g m\n", t, p->k[t],
        p->r0[t], p->rmax[t]));
  PetscFunctionReturn(0);
}

PetscErrorCode bond_nonlinear_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "bond_nonlinear";
  static const char *const reads[] = {"x", NULL}; /* ghost positions */
  (*m)->ghost_reads = reads;
  (*m)->solid_internal = PETSC_TRUE;
  (*m)->needs = MODULE_NEEDS_BONDS;
  (*m)->set_from_options = bond_nonlinear_set_from_options;
  (*m)->setup = bond_nonlinear_setup;
  (*m)->compute = bond_nonlinear_compute;
  (*m)->max_dt = bond_nonlinear_max_dt;
  (*m)->jacobian_blocks = bond_nonlinear_jacobian;
  (*m)->view = bond_nonlinear_view;
  (*m)->destroy = bond_destroy;
  (*m)->energy = bond_nonlinear_energy_sum;
  (*m)->virial = bond_nonlinear_virial;
  PetscCall(PetscNew((bond_nonlinear_data **)&(*m)->data));
  /* the colon membrane's bonds (doc/cases.md) until a scene or the options say otherwise */
  bond_params *p = (*m)->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++) {
    p->k[t] = 1e-4;
    p->r0[t] = 2.5e-4;
    p->rmax[t] = 4.5e-4;
  }
  PetscFunctionReturn(0);
}
