/* Module solid_load: a point load and viscous damping on solid particles.
 *   a_i += F / (n_tagged m_i)     for particles with load = SOLID_LOAD_MARK
 *   a_i -= gamma v_est_i          for solid particles (v_est: the predicted
 *                                 velocity at the force evaluation)
 * Options -solid_load_force Fx,Fy [N], -solid_damping gamma [1/s]. The load's
 * potential energy -F . (x - x0) summed over tagged particles is its energy. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/fields.h"
#include "dmhs/solid_load.h"
#include "dmhs/events.h"

typedef struct {
  double F[DMHS_DIM]; /* [N] */
  double gamma;       /* [1/s] */
  PetscInt n_tagged;  /* over all ranks */
} solid_load_data;

PetscErrorCode solid_load_set_default(module *m, double fx, double fy, double gamma) {
  solid_load_data *d = m->data;
  PetscFunctionBeginUser;
  d->F[0] = fx;
  d->F[1] = fy;
  d->gamma = gamma;
  PetscFunctionReturn(0);
}

PetscErrorCode solid_load_get_force(module *m, double F[2]) {
  const solid_load_data *d = m->data;
  PetscFunctionBeginUser;
  F[0] = d->F[0];
  F[1] = d->F[1];
  PetscFunctionReturn(0);
}

PetscErrorCode solid_load_get_damping(module *m, double *gamma) {
  const solid_load_data *d = m->data;
  PetscFunctionBeginUser;
  *gamma = d->gamma;
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_set_from_options(module *self, sim *s) {
  solid_load_data *d = self->data;
  PetscInt n = DMHS_DIM;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscCall(fields_enable("load")); /* which particles carry the load */
  PetscCall(fields_enable("x0"));   /* the load's work, from the initial positions */
  PetscOptionsBegin(s->comm, NULL, "Point load and damping on solids (module solid_load)", NULL);
  PetscCall(options_read_real_array("-solid_load_force",
                                    "Point load Fx,Fy [N] shared by the marked particles (tip)",
                                    NULL, d->F, &n, &set));
  PetscCall(options_read_real("-solid_damping",
                              "Viscous damping rate gamma [1/s] on solid particles (a -= gamma v)",
                              NULL, d->gamma, &d->gamma, NULL));
  PetscOptionsEnd();
  PetscCheck(!set || n == DMHS_DIM, s->comm, PETSC_ERR_ARG_SIZ,
             "-solid_load_force takes %d components Fx,Fy (got %d)", DMHS_DIM, (int)n);
  PetscCheck(d->gamma >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-solid_damping must be >= 0 (got %g 1/s)", d->gamma);
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_setup(module *self, sim *s) {
  solid_load_data *d = self->data;
  PetscInt local = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    local += s->ps.load[i] == SOLID_LOAD_MARK;
  PetscCallMPI(MPI_Allreduce(&local, &d->n_tagged, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscCheck(d->n_tagged > 0 || (d->F[0] == 0 && d->F[1] == 0), s->comm, PETSC_ERR_ARG_WRONG,
             "-solid_load_force given but the scene marks no particle to carry it");
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_compute(module *self, sim *s) {
  const solid_load_data *d = self->data;
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.solid_load, 0, 0, 0, 0));
  const double share[2] = {d->n_tagged ? d->F[0] / d->n_tagged : 0,
                           d->n_tagged ? d->F[1] / d->n_tagged : 0};
  const double g = d->gamma;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_SOLID)
      continue;
    ps->a[i][0] -= g * ps->v_est[i][0];
    ps->a[i][1] -= g * ps->v_est[i][1];
    if (ps->load[i] == SOLID_LOAD_MARK) {
      ps->a[i][0] += share[0] / ps->mass[i];
      ps->a[i][1] += share[1] / ps->mass[i];
    }
  }
  PetscCall(PetscLogFlops(4.0 * (double)ps->n_owned));
  PetscCall(PetscLogEventEnd(events.solid_load, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_energy(module *self, sim *s, double *e) {
  const solid_load_data *d = self->data;
  const particles *ps = &s->ps;
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_SOLID && ps->load[i] == SOLID_LOAD_MARK)
      local -= (d->F[0] * (ps->x[i][0] - ps->x0[i][0]) + d->F[1] * (ps->x[i][1] - ps->x0[i][1])) /
               d->n_tagged;
  PetscCallMPI(MPI_Allreduce(&local, e, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

/* damping: explicit decay a = -gamma v is stable for gamma dt < 2; keep 0.2/gamma */
static PetscErrorCode solid_load_max_dt(module *self, sim *s, dt_limits *l) {
  const solid_load_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  if (d->gamma > 0)
    PetscCall(dt_limits_add(l, "solid damping", "0.2/gamma", 0.2 / d->gamma));
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_view(module *self, sim *s, PetscViewer v) {
  const solid_load_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "solid_load: point load (%g, %g) N on %" PetscInt_FMT
                                   " tagged particles, damping %g 1/s on solids\n",
                                   d->F[0], d->F[1], d->n_tagged, d->gamma));
  PetscFunctionReturn(0);
}

static PetscErrorCode solid_load_destroy(module *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode solid_load_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "solid_load";
  (*m)->set_from_options = solid_load_set_from_options;
  (*m)->setup = solid_load_setup;
  (*m)->compute = solid_load_compute;
  (*m)->max_dt = solid_load_max_dt;
  (*m)->view = solid_load_view;
  (*m)->destroy = solid_load_destroy;
  (*m)->energy = solid_load_energy;
  PetscCall(PetscNew((solid_load_data **)&(*m)->data));
  PetscFunctionReturn(0);
}
