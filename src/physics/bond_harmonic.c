/* Module bond_harmonic: U = K (r - r0)^2 per bond (doc/theory.md), K [J/m^2] and r0 [m]
 * per bond type (-bond_k, -bond_r0), with an optional dashpot on each bond's length
 * (-bond_damping, dashpot_iact.h). Pair arithmetic in bond_iact.h. It claims the
 * scene's bond types at setup; types another module claimed (the clots',
 * agglomeration.c) are left to that module, which applies the same law to them through
 * bond_harmonic_forces with each bond's own rest length.
 * Time-step limit: SPRING_DT_FACTOR sqrt(m/k) with k = U'' = 2K. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/bond.h"
#include "dmhs/events.h"
#include "dmhs/solid_modes.h"
#include "bond_iact.h"
#include "dashpot_iact.h"
#include "virial_iact.h"

static PetscErrorCode bond_harmonic_set_from_options(module *self, sim *s) {
  bond_params *p = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Harmonic bonds U = K (r - r0)^2 (module bond_harmonic)", NULL);
  PetscCall(bond_options_k_r0(
      PetscOptionsObject, p,
      "Bond stiffness K [J/m^2] (U = K (r-r0)^2), one value or one per bond type"));
  PetscCall(options_read_real(
      "-bond_damping",
      "Damping ratio zeta of a dashpot on every bond's length [1] (0 = none; 0.01 lets the "
      "sub-cycled solids take a step past their fastest-mode resonance: doc/stability.md)",
      NULL, p->damping, &p->damping, NULL));
  PetscOptionsEnd();
  PetscCheck(p->damping >= 0 && p->damping < 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-bond_damping must lie in [0, 1) (got %g)", p->damping);
  /* the dashpot reads the partners' velocities */
  static const char *const reads_xv[] = {"x", "v", NULL};
  if (p->damping > 0)
    self->ghost_reads = reads_xv;
  double r0max = 0;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++)
    r0max = PetscMax(r0max, p->r0[t]);
  /* the ghost width must reach a stretched partner; 1.5 r0 is far beyond any sane stretch */
  self->reach = 1.5 * r0max;
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_harmonic_setup(module *self, sim *s) {
  PetscFunctionBeginUser;
  PetscCall(bond_claim_scene_types(s, self));
  PetscCall(bond_setup_k_r0(s, self->data, "J/m^2"));
  PetscFunctionReturn(0);
}

/* r0 of local bond entry b: its type's, or (r0 NULL) its own (topology bond_r0) */
#define HARMONIC_R0(set, t, b, ty) ((set)->r0 ? (set)->r0[ty] : (t)->bond_r0[(t)->bond_index[b]])

/* One pass over the set's bonds, tallying what is asked (the LAMMPS ev_tally idea): forces
 * into a (a is not NULL), the pair virial into W (both ends get -1/2 d (x) F_i, F_i = fr d)
 * and the weighted energy into *e. force, virial, energy are constants at each call below, so
 * each use compiles to its own loop; the forces' arithmetic is the step's whatever else is
 * tallied. */
static inline void harmonic_tally(const sim *s, const harmonic_bonds *set, int force, int virial,
                                  int energy, double (*restrict W)[3], double *e) {
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  const PetscInt nb = t->n_bond_local;
  const PetscInt(*restrict bond)[2] = (const PetscInt(*)[2])t->bond;
  const PetscInt *restrict type = t->bond_ltype;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double(*restrict v)[2] = (const double(*)[2])ps->v;
  const double *restrict mass = ps->mass;
  const double *restrict K = set->k;
  const double zeta = set->damping;
  double(*restrict a)[2] = ps->a;
  const void *const *restrict owner = t->bond_owner;
  double local = 0;
  for (PetscInt b = 0; b < nb; b++) {
    const PetscInt i = bond[b][0], j = bond[b][1], ty = type[b];
    if (owner[ty] != set->owner) /* another module's bond type */
      continue;
    const double d[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double r = sqrt(d[0] * d[0] + d[1] * d[1]), r0 = HARMONIC_R0(set, t, b, ty);
    if (force || virial) {
      double fr = bond_harmonic_iact(K[ty], r0, r);
      if (zeta > 0) {
        const double dv[2] = {v[i][0] - v[j][0], v[i][1] - v[j][1]};
        fr += bond_dashpot_iact(bond_dashpot_gamma(zeta, 2.0 * K[ty], mass[i], mass[j]), d, r, dv);
      }
      bond_pair_apply(a, W, mass, i, j, fr, d, force, virial);
    }
    if (energy)
      local += t->bond_weight[b] * bond_harmonic_energy(K[ty], r0, r);
  }
  if (energy)
    *e = local;
}

PetscErrorCode bond_harmonic_forces(sim *s, const harmonic_bonds *set) {
  PetscFunctionBeginUser;
  harmonic_tally(s, set, 1, 0, 0, NULL, NULL);
  PetscCall(PetscLogFlops(20.0 * (double)s->topo->n_bond_local));
  PetscFunctionReturn(0);
}

PetscErrorCode bond_harmonic_virial_add(sim *s, const harmonic_bonds *set, double (*W)[3]) {
  PetscFunctionBeginUser;
  harmonic_tally(s, set, 0, 1, 0, W, NULL);
  PetscFunctionReturn(0);
}

PetscErrorCode bond_harmonic_energy_of(sim *s, const harmonic_bonds *set, double *e) {
  double local = 0;
  PetscFunctionBeginUser;
  harmonic_tally(s, set, 0, 0, 1, NULL, &local);
  PetscCallMPI(MPI_Allreduce(&local, e, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

/* the module's bonds: the types it claimed, K and r0 per type */
static harmonic_bonds bond_harmonic_set(const module *self) {
  const bond_params *p = self->data;
  return (harmonic_bonds){.owner = self, .k = p->k, .r0 = p->r0, .damping = p->damping};
}

static PetscErrorCode bond_harmonic_compute(module *self, sim *s) {
  const harmonic_bonds set = bond_harmonic_set(self);
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.bond, 0, 0, 0, 0));
  PetscCall(bond_harmonic_forces(s, &set));
  PetscCall(PetscLogEventEnd(events.bond, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_harmonic_virial(module *self, sim *s, double (*W)[3]) {
  const harmonic_bonds set = bond_harmonic_set(self);
  PetscFunctionBeginUser;
  PetscCall(bond_harmonic_virial_add(s, &set, W));
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_harmonic_energy_sum(module *self, sim *s, double *e) {
  const harmonic_bonds set = bond_harmonic_set(self);
  PetscFunctionBeginUser;
  PetscCall(bond_harmonic_energy_of(s, &set, e));
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_harmonic_max_dt(module *self, sim *s, dt_limits *l) {
  const bond_params *p = self->data;
  double kmax = 0;
  PetscFunctionBeginUser;
  for (PetscInt t = 0; t < s->topo->n_bond_types; t++)
    kmax = PetscMax(kmax, 2.0 * p->k[t]);
  if (kmax > 0 && isfinite(p->m_min))
    PetscCall(dt_limits_add(l, "bond harmonic", "0.2 sqrt(m/k), k = U'' = 2K, m = min solid mass",
                            SPRING_DT_FACTOR * sqrt(p->m_min / kmax)));
  PetscFunctionReturn(0);
}

/* Jacobian blocks (module.h): U'' = 2K along the bond, U'/r across. */
static PetscErrorCode bond_harmonic_jacobian(module *self, sim *s, solid_jacobian *J) {
  const bond_params *p = self->data;
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    const PetscInt i = t->bond[b][0], j = t->bond[b][1], ty = t->bond_ltype[b];
    if (t->bond_owner[ty] != self)
      continue;
    const double d[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double r = sqrt(d[0] * d[0] + d[1] * d[1]);
    PetscCall(bond_jacobian_add(J, i, j, d, r, 2.0 * p->k[ty],
                                bond_harmonic_iact(p->k[ty], p->r0[ty], r)));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode bond_harmonic_view(module *self, sim *s, PetscViewer v) {
  const bond_params *p = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(
      v,
      "bond_harmonic: %" PetscInt64_FMT " bonds, U = K (r - r0)^2; 1-2/1-3 partners %s pair sums\n",
      s->topo->n_bonds_global, s->topo->special_include ? "included in" : "excluded from"));
  if (p->damping > 0)
    PetscCall(PetscViewerASCIIPrintf(v, "  dashpots on the bonds' lengths: damping ratio %g\n",
                                     p->damping));
  for (PetscInt t = 0; t < s->topo->n_bond_types; t++)
    PetscCall(PetscViewerASCIIPrintf(v, "  bond type %" PetscInt_FMT ": K = %g J/m^2, r0 = %g m\n",
                                     t, p->k[t], p->r0[t]));
  PetscFunctionReturn(0);
}

PetscErrorCode bond_harmonic_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "bond_harmonic";
  static const char *const reads[] = {"x", NULL}; /* ghost positions */
  (*m)->ghost_reads = reads;
  (*m)->solid_internal = PETSC_TRUE;
  (*m)->needs = MODULE_NEEDS_BONDS;
  (*m)->set_from_options = bond_harmonic_set_from_options;
  (*m)->setup = bond_harmonic_setup;
  (*m)->compute = bond_harmonic_compute;
  (*m)->max_dt = bond_harmonic_max_dt;
  (*m)->jacobian_blocks = bond_harmonic_jacobian;
  (*m)->view = bond_harmonic_view;
  (*m)->destroy = bond_destroy;
  (*m)->energy = bond_harmonic_energy_sum;
  (*m)->virial = bond_harmonic_virial;
  PetscCall(PetscNew((bond_params **)&(*m)->data));
  /* the vein leaflets' bonds (doc/cases.md) until a scene or the options say otherwise */
  bond_params *p = (*m)->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++) {
    p->k[t] = 1e6;
    p->r0[t] = 1e-4;
  }
  PetscFunctionReturn(0);
}
