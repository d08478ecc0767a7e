/* Scene cantilever (no liquid): a two-layer mass-spring strip built the way the
 * vein leaflets are (doc/cases.md), clamped at its left end, loaded at its tip.
 * It validates the Timoshenko mapping of doc/theory.md:
 *   EI = k_s r0^3/2 + 2 k_a r0 (k_s = U''(r0): 2K harmonic, 2 k_b/r_max^2 nonlinear),
 *   kGA = 8 k_a/r0, mu = 2m/r0, L = (n - n_clamp) r0,
 *   static tip deflection w = F L^3/(3 EI) + F L/(kGA),
 *   first frequency 1/w1^2 = 1/wb^2 + 1/ws^2 (Dunkerley), wb = 1.8751^2 sqrt(EI/(mu L^4)),
 *   ws = (pi/2) sqrt(kGA/(mu L^2)).
 * Output: the diagnostic "cantilever" (cantilever.csv, src/scenes/cantilever/cantilever_tip.c). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/solid_load.h"
#include "cantilever_tip.h"
#include "scenes/solid_strip.h"

typedef struct {
  solid_strip st;
  module *load;
  double EI, kGA, mu, L; /* beam constants */
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
  PetscCall(options_read_int("-cantilever_n", "Columns of particles, clamped ones included [1]",
                             NULL, c->st.n, &c->st.n, NULL));
  PetscCall(options_read_int("-cantilever_clamp", "Clamped columns at the left end [1]", NULL,
                             c->st.n_clamp, &c->st.n_clamp, NULL));
  PetscCall(options_read_real("-cantilever_mass", "Mass of one particle [kg] (per unit depth)",
                              NULL, c->st.mass, &c->st.mass, NULL));
  PetscOptionsEnd();
  PetscCheck(c->st.n_clamp >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cantilever_clamp must be >= 1 (got %" PetscInt_FMT ")", c->st.n_clamp);
  PetscCheck(c->st.n >= c->st.n_clamp + 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cantilever_n must be >= %" PetscInt_FMT " (-cantilever_clamp + 2; got %" PetscInt_FMT
             ")",
             c->st.n_clamp + 2, c->st.n);
  PetscCheck(c->st.mass > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-cantilever_mass must be > 0 kg (got %g)", c->st.mass);
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
  const cantilever_beam beam = {.n = c->st.n,
                                .n_clamp = c->st.n_clamp,
                                .spacing = c->st.spacing,
                                .mass = c->st.mass,
                                .L = c->L,
                                .EI = c->EI,
                                .kGA = c->kGA,
                                .mu = c->mu,
                                .load = c->load};
  PetscCall(cantilever_tip_register(s, &beam));
  PetscFunctionReturn(0);
}

static PetscErrorCode cantilever_destroy(scene *self) {
  PetscFunctionBeginUser;
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
  (*out)->destroy = cantilever_destroy;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
