/* Scene cantilever (no liquid): a two-layer mass-spring strip built the way the
 * vein leaflets are (doc/cases.md), clamped at its left end, loaded at its tip.
 * It validates the Timoshenko mapping of doc/theory.md:
 *   EI = k_s r0^3/2 + 2 k_a r0 (k_s = U''(r0): 2K harmonic, 2 k_b/r_max^2 nonlinear),
 *   kGA = 8 k_a/r0, mu = 2m/r0, L = (n - n_clamp) r0,
 *   static tip deflection w = F L^3/(3 EI) + F L/(kGA),
 *   first frequency 1/w1^2 = 1/wb^2 + 1/ws^2 (Dunkerley), wb = 1.8751^2 sqrt(EI/(mu L^4)),
 *   ws = (pi/2) sqrt(kGA/(mu L^2)).
 * Output: <output_dir>/cantilever.csv, one row per output interval:
 *   t, tip_dx, tip_dy (mean displacement of the tip column [m]), kinetic and
 *   potential energy [J]; header lines '# key = value' give the beam constants,
 *   the load F [N] and the damping rate gamma [1/s] (scripts/post/plot_cantilever.py).
 *   A restart continues the file (csv.h). */
#include <math.h>
#include <errno.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/solid_load.h"
#include "dmhs/csv.h"
#include "solid_strip.h"

typedef struct {
  solid_strip st;
  module *load;
  double EI, kGA, mu, L, F; /* beam constants, tip load |F_y| */
  FILE *csv;
} cantilever_data;

/* scene defaults: the vein leaflet (doc/cases.md) */
#define CANTILEVER_K    1e6
#define CANTILEVER_R0   1e-4
#define CANTILEVER_KA   0.01
#define CANTILEVER_MASS 2e-5

static PetscErrorCode cantilever_set_from_options(scene *self, sim *s) {
  cantilever_data *c = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL,
                    "Scene cantilever (two-layer mass-spring beam, clamped, tip load)", NULL);
  PetscCall(PetscOptionsInt("-cantilever_n", "Columns of particles, clamped ones included [1]",
                            NULL, c->st.n, &c->st.n, NULL));
  PetscCall(PetscOptionsInt("-cantilever_clamp", "Clamped columns at the left end [1]", NULL,
                            c->st.n_clamp, &c->st.n_clamp, NULL));
  PetscCall(PetscOptionsReal("-cantilever_mass", "Mass of one particle [kg] (per unit depth)", NULL,
                             c->st.mass, &c->st.mass, NULL));
  PetscOptionsEnd();
  PetscCheck(c->st.n_clamp >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cantilever_clamp must be >= 1");
  PetscCheck(c->st.n >= c->st.n_clamp + 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cantilever_n must be >= -cantilever_clamp + 2 (got %" PetscInt_FMT ")", c->st.n);
  PetscCheck(c->st.mass > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-cantilever_mass must be > 0");
  PetscCall(fields_enable("x0")); /* the tip's deflection */
  PetscCall(solid_modules_enable(s, BOND_HARMONIC));
  PetscCall(bond_set_default(s, CANTILEVER_K, CANTILEVER_R0, 0.5 * CANTILEVER_R0));
  PetscCall(angle_set_default(s, CANTILEVER_KA, 90.0));
  PetscCall(modules_enable(s, "solid_load", &c->load));
  /* default load: 1 % of L tip deflection, and damping near the first
   * frequency, both for the default beam (override with -solid_load_force, -solid_damping) */
  double EI, kGA, mu;
  const double L = (c->st.n - c->st.n_clamp) * CANTILEVER_R0;
  solid_strip_beam(2 * CANTILEVER_K, CANTILEVER_KA, CANTILEVER_R0, c->st.mass, &EI, &kGA, &mu);
  const double compliance = L * L * L / (3 * EI) + L / kGA;
  const double wb = 1.8751 * 1.8751 * sqrt(EI / (mu * L * L * L * L)),
               ws = 0.5 * M_PI * sqrt(kGA / (mu * L * L));
  PetscCall(solid_load_set_default(c->load, 0.0, -0.01 * L / compliance,
                                   1.0 / sqrt(1 / (wb * wb) + 1 / (ws * ws))));
  PetscFunctionReturn(0);
}

/* cantilever.csv with its '# key = value' header (csv.h: a restart continues it) */
static PetscErrorCode cantilever_open_csv(cantilever_data *c, sim *s) {
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
  PetscCall(solid_load_get_force(c->load, F));
  c->F = -F[1]; /* downward tip load */
  PetscCall(solid_load_get_damping(c->load, &gamma));
  PetscCall(angle_get_params(s, &ka, &th0));
  snprintf(header, sizeof(header),
           "# cantilever: two-layer mass-spring strip (doc/theory.md)\n"
           "# n = %d\n# n_clamp = %d\n# r0 = %.10g\n# mass = %.10g\n# k_s = %.10g\n# k_a = %.10g\n"
           "# L = %.10g\n# EI = %.10g\n# kGA = %.10g\n# mu = %.10g\n# F = %.10g\n# gamma = %.10g\n"
           "# dt = %.10g\n"
           "t,tip_dx,tip_dy,kinetic,potential\n",
           (int)c->st.n, (int)c->st.n_clamp, c->st.spacing, c->st.mass, k_s, ka, c->L, c->EI,
           c->kGA, c->mu, c->F, gamma, s->dt);
  PetscCall(csv_open(s, "cantilever.csv", header, &c->csv));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_build(scene *self, sim *s) {
  cantilever_data *c = self->data;
  bond_style style;
  const bond_params *bp;
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  PetscCall(bond_get_params(s, &style, &bp));
  const double r0 = bp->r0[0];
  const double k_s =
      style == BOND_HARMONIC ? 2 * bp->k[0] : 2 * bp->k[0] / (bp->rmax[0] * bp->rmax[0]);
  double ka, th0;
  PetscCall(angle_get_params(s, &ka, &th0));
  c->st.spacing = r0;
  c->st.rho = 1000.0;
  c->st.origin[0] = c->st.origin[1] = 0;
  c->st.along[0] = 1;
  c->st.along[1] = 0;
  c->st.across[0] = 0;
  c->st.across[1] = 1;
  c->L = (c->st.n - c->st.n_clamp) * r0;
  s->dx = r0;
  /* a box the beam cannot leave in any sane run: closed on every side */
  const double len = (c->st.n - 1) * r0;
  s->dom.lo[0] = -0.5 * len - 2 * r0;
  s->dom.hi[0] = 1.5 * len + 2 * r0;
  s->dom.lo[1] = -1.5 * len - 2 * r0;
  s->dom.hi[1] = 1.5 * len + 2 * r0;
  s->dom.periodic[0] = s->dom.periodic[1] = PETSC_FALSE;
  PetscCall(solid_strip_build(s, &c->st, &gid));
  solid_strip_beam(k_s, ka, r0, c->st.mass, &c->EI, &c->kGA, &c->mu);
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_tip(sim *s, double d[2]) {
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

static PetscErrorCode cantilever_diagnose(scene *self, sim *s) {
  cantilever_data *c = self->data;
  double d[2], kin = 0, pot = 0;
  PetscFunctionBeginUser;
  /* rows at step 0 and at output times */
  if (s->step > 0 && s->t < s->next_output_t - 0.5 * s->dt)
    PetscFunctionReturn(0);
  if (!c->csv)
    PetscCall(cantilever_open_csv(c, s));
  PetscCall(cantilever_tip(s, d));
  PetscCall(cantilever_energies(s, &kin, &pot));
  if (c->csv)
    PetscCall(csv_row(c->csv, "cantilever.csv", "%.10g,%.10g,%.10g,%.10g,%.10g\n", s->t, d[0], d[1],
                      kin, pot));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_finish(scene *self, sim *s) {
  cantilever_data *c = self->data;
  double d[2];
  PetscFunctionBeginUser;
  PetscCall(cantilever_tip(s, d));
  PetscCall(PetscPrintf(
      s->comm,
      "cantilever: L = %g m, EI = %g N m^2, kGA = %g N; final tip displacement (%g, %g) m; see "
      "cantilever.csv and test/validation/cantilever.py\n",
      c->L, c->EI, c->kGA, d[0], d[1]));
  PetscCall(csv_close(&c->csv, "cantilever.csv"));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_destroy(scene *self) {
  cantilever_data *c = self->data;
  PetscFunctionBeginUser;
  if (c->csv)
    fclose(c->csv);
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode cantilever_scene_create(scene **out) {
  cantilever_data *c;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&c));
  c->st.n = 21;
  c->st.n_clamp = 1;
  c->st.mass = CANTILEVER_MASS;
  (*out)->name = "cantilever";
  (*out)->set_from_options = cantilever_set_from_options;
  (*out)->build = cantilever_build;
  (*out)->diagnose = cantilever_diagnose;
  (*out)->finish = cantilever_finish;
  (*out)->destroy = cantilever_destroy;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
