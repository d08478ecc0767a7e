/* The diagnostic "cantilever": tip displacement and energies of the loaded
 * beam (cantilever_tip.h). */
#include <math.h>
#include "cantilever_tip.h"
#include "dmhs/diagnostics.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/solid_load.h"
#include "dmhs/csv.h"

typedef struct {
  cantilever_beam beam;
  FILE *csv;
} cantilever_tip;

/* cantilever.csv with its '# key = value' header (csv.h: a restart continues it) */
static PetscErrorCode cantilever_open_csv(cantilever_tip *c, sim *s) {
  const cantilever_beam *b = &c->beam;
  char header[1024];
  bond_style style;
  const bond_params *bp;
  double F[2], ka, th0, gamma;
  PetscFunctionBeginUser;
  if (s->rank)
    PetscFunctionReturn(0);
  PetscCall(bond_get_params(s, &style, &bp));
  const double k_s =
      style == BOND_HARMONIC ? 2 * bp->k[0] : 2 * bp->k[0] / (bp->rmax[0] * bp->rmax[0]);
  PetscCall(solid_load_get_force(b->load, F));
  PetscCall(solid_load_get_damping(b->load, &gamma));
  PetscCall(angle_get_params(s, &ka, &th0));
  snprintf(header, sizeof(header),
           "# cantilever: two-layer mass-spring strip (doc/theory.md)\n"
           "# n = %d\n# n_clamp = %d\n# r0 = %.10g\n# mass = %.10g\n# k_s = %.10g\n# k_a = %.10g\n"
           "# L = %.10g\n# EI = %.10g\n# kGA = %.10g\n# mu = %.10g\n# F = %.10g\n# gamma = %.10g\n"
           "# dt = %.10g\n"
           "t,tip_dx,tip_dy,kinetic,potential\n",
           (int)b->n, (int)b->n_clamp, b->spacing, b->mass, k_s, ka, b->L, b->EI, b->kGA, b->mu,
           -F[1] /* downward tip load */, gamma, s->dt);
  PetscCall(csv_open(s, "cantilever.csv", header, &c->csv));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_tip_displacement(sim *s, double d[2]) {
  const particles *ps = &s->ps;
  double local[3] = {0, 0, 0}, global[3];
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->load[i] == SOLID_LOAD_MARK) {
      local[0] += ps->x[i][0] - ps->x0[i][0];
      local[1] += ps->x[i][1] - ps->x0[i][1];
      local[2] += 1;
    }
  PetscCallMPI(MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_SUM, s->comm));
  d[0] = global[0] / global[2];
  d[1] = global[1] / global[2];
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_energies(sim *s, double *kin, double *pot) {
  double local = 0, e;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (s->ps.type[i] != PTYPE_WALL)
      local +=
          0.5 * s->ps.mass[i] * (s->ps.v[i][0] * s->ps.v[i][0] + s->ps.v[i][1] * s->ps.v[i][1]);
  PetscCallMPI(MPI_Allreduce(&local, kin, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  *pot = 0;
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->energy) {
      PetscCall(s->modules[m]->energy(s->modules[m], s, &e));
      *pot += e;
    }
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_tip_sample(diagnostic *self, sim *s) {
  cantilever_tip *c = self->data;
  double d[2], kin = 0, pot = 0;
  PetscFunctionBeginUser;
  if (!c->csv)
    PetscCall(cantilever_open_csv(c, s));
  PetscCall(cantilever_tip_displacement(s, d));
  PetscCall(cantilever_energies(s, &kin, &pot));
  if (c->csv)
    PetscCall(csv_row(c->csv, "cantilever.csv", "%.10g,%.10g,%.10g,%.10g,%.10g\n", s->t, d[0], d[1],
                      kin, pot));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_tip_finish(diagnostic *self, sim *s) {
  cantilever_tip *c = self->data;
  double d[2];
  PetscFunctionBeginUser;
  PetscCall(cantilever_tip_displacement(s, d));
  PetscCall(PetscPrintf(
      s->comm,
      "cantilever: L = %g m, EI = %g N m^2, kGA = %g N; final tip displacement (%g, %g) m; see "
      "cantilever.csv and test/validation/cantilever.py\n",
      c->beam.L, c->beam.EI, c->beam.kGA, d[0], d[1]));
  PetscCall(csv_close(&c->csv, "cantilever.csv"));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_tip_destroy(diagnostic *self) {
  cantilever_tip *c = self->data;
  PetscFunctionBeginUser;
  if (c->csv)
    fclose(c->csv);
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode cantilever_tip_register(sim *s, const cantilever_beam *beam) {
  diagnostic *d;
  cantilever_tip *c;
  PetscFunctionBeginUser;
  PetscCall(diagnostic_create("cantilever", &d));
  PetscCall(PetscNew(&c));
  c->beam = *beam;
  d->data = c;
  d->output = "cantilever.csv";
  d->when.at_outputs = PETSC_TRUE;
  d->sample = cantilever_tip_sample;
  d->finish = cantilever_tip_finish;
  d->destroy = cantilever_tip_destroy;
  PetscCall(diagnostics_add(s, d));
  PetscFunctionReturn(0);
}
