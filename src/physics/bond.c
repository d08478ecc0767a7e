/* What the two bond modules share: the -bond_style names, scene defaults,
 * per-type coefficient checks, and the helpers their time-step limits use. */
#include <math.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/modules.h"
#include "dmhs/bond.h"
#include "dmhs/solid_modes.h"

const char *const bond_style_names[] = {"harmonic", "nonlinear", "bond_style", "BOND_", NULL};

PetscErrorCode bond_options_k_r0(PetscOptionItems *PetscOptionsObject, bond_params *p,
                                 const char *k_help) {
  PetscInt n = TOPOLOGY_MAX_TYPES;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscCall(options_read_real_array("-bond_k", k_help, NULL, p->k, &n, &set));
  p->n_k = set ? n : 0;
  n = TOPOLOGY_MAX_TYPES;
  PetscCall(options_read_real_array("-bond_r0",
                                    "Bond rest length r0 [m], one value or one per bond type", NULL,
                                    p->r0, &n, &set));
  p->n_r0 = set ? n : 0;
  PetscFunctionReturn(0);
}

PetscErrorCode bond_setup_k_r0(sim *s, bond_params *p, const char *k_unit) {
  const PetscInt nt = s->topo->n_bond_types;
  PetscFunctionBeginUser;
  PetscCall(bond_check_type_coeffs("-bond_k", p->k, p->n_k, nt));
  PetscCall(bond_check_type_coeffs("-bond_r0", p->r0, p->n_r0, nt));
  for (PetscInt t = 0; t < nt; t++) {
    PetscCheck(p->k[t] > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-bond_k must be > 0 (type %" PetscInt_FMT ": %g %s)", t, p->k[t], k_unit);
    PetscCheck(p->r0[t] > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-bond_r0 must be > 0 (type %" PetscInt_FMT ": %g m)", t, p->r0[t]);
  }
  PetscCall(bond_min_solid_mass(s, &p->m_min));
  PetscFunctionReturn(0);
}

PetscErrorCode bond_claim_scene_types(sim *s, const module *self) {
  PetscFunctionBeginUser;
  for (PetscInt ty = 0; ty < s->topo->n_bond_types; ty++)
    if (!s->topo->bond_owner[ty])
      PetscCall(topology_claim_bond_type(s->topo, ty, self));
  PetscFunctionReturn(0);
}

PetscErrorCode bond_destroy(module *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

static module *bond_find(sim *s) {
  for (int m = 0; m < s->n_modules; m++)
    if (!strcmp(s->modules[m]->name, "bond_harmonic") ||
        !strcmp(s->modules[m]->name, "bond_nonlinear"))
      return s->modules[m];
  return NULL;
}

PetscErrorCode bond_set_default(sim *s, double k, double r0, double rmax) {
  module *m = bond_find(s);
  PetscFunctionBeginUser;
  PetscCheck(m, s->comm, PETSC_ERR_ORDER,
             "bond_set_default: no bond module enabled (call solid_modules_enable first)");
  bond_params *p = m->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++) {
    p->k[t] = k;
    p->r0[t] = r0;
    p->rmax[t] = rmax;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode bond_get_params(sim *s, bond_style *style, const bond_params **p) {
  module *m = bond_find(s);
  PetscFunctionBeginUser;
  PetscCheck(m, s->comm, PETSC_ERR_ORDER, "no bond module enabled");
  *style = !strcmp(m->name, "bond_harmonic") ? BOND_HARMONIC : BOND_NONLINEAR;
  *p = m->data;
  PetscFunctionReturn(0);
}

PetscErrorCode bond_check_type_coeffs(const char *option, double v[], PetscInt n_given,
                                      PetscInt n_types) {
  PetscFunctionBeginUser;
  if (n_given == 1)
    for (int t = 1; t < TOPOLOGY_MAX_TYPES; t++)
      v[t] = v[0];
  else
    PetscCheck(n_given == 0 || n_given >= n_types, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
               "%s: %" PetscInt_FMT " values given but the structure uses %" PetscInt_FMT
               " types (give one value for every type, or one per type)",
               option, n_given, n_types);
  PetscFunctionReturn(0);
}

PetscErrorCode bond_check_resolved(const sim *s, const char *who) {
  PetscFunctionBeginUser;
  PetscCheck(s->topo->resolved, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "%s: the bonds' and angles' local lists are asked for before the first neighbour "
             "build",
             who);
  PetscFunctionReturn(0);
}

PetscErrorCode bond_min_solid_mass(sim *s, double *m) {
  double local = INFINITY;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (s->ps.type[i] == PTYPE_SOLID)
      local = PetscMin(local, s->ps.mass[i]);
  PetscCallMPI(MPI_Allreduce(&local, m, 1, MPI_DOUBLE, MPI_MIN, s->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode solid_modules_enable(sim *s, bond_style style) {
  PetscBool include = s->topo ? s->topo->special_include : PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Solids: bonds, angles and exclusions", NULL);
  PetscCall(options_read_enum(
      "-bond_style",
      "Bond potential: harmonic K (r-r0)^2 or nonlinear k_b (r-r0)^2/(r_max^2-(r-r0)^2)", NULL,
      bond_style_names, (PetscEnum)style, (PetscEnum *)&style, NULL));
  PetscCall(options_read_bool(
      "-special_bonds_include",
      "Keep bonded 1-2 and 1-3 partners in SPH and repulsion sums (default: excluded, as "
      "LAMMPS special_bonds lj/coul 0 0 1 angle yes)",
      NULL, include, &include, NULL));
  PetscOptionsEnd();
  /* the bond and angle modules ask for the store (MODULE_NEEDS_BONDS, _ANGLES) */
  PetscCall(modules_enable(s, style == BOND_HARMONIC ? "bond_harmonic" : "bond_nonlinear", NULL));
  PetscCall(modules_enable(s, "angle_harmonic", NULL));
  s->topo->special_include = include;
  PetscFunctionReturn(0);
}

PetscErrorCode bond_jacobian_add(solid_jacobian *J, PetscInt i, PetscInt j, const double d[2],
                                 double r, double upp, double fr) {
  const double u[2] = {d[0] / r, d[1] / r}, across = -fr;
  double A[2][2], minus[2][2];
  PetscFunctionBeginUser;
  for (int a = 0; a < 2; a++)
    for (int b = 0; b < 2; b++) {
      A[a][b] = (upp - across) * u[a] * u[b] + (a == b ? across : 0.0);
      minus[a][b] = -A[a][b];
    }
  PetscCall(solid_jacobian_add(J, i, i, A));
  PetscCall(solid_jacobian_add(J, j, j, A));
  PetscCall(solid_jacobian_add(J, i, j, minus));
  PetscCall(solid_jacobian_add(J, j, i, minus));
  PetscFunctionReturn(0);
}
