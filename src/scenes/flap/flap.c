/* Scene flap (a coupled check): a flexible two-layer mass-spring flap
 * (solid_strip, SPH + bonds + angles) standing on the lower wall of a
 * periodic channel flow driven by a body force on the liquid. The flap's
 * lowest row is part of the wall (clamped). The liquid sees the flap through
 * the SPH sums (no-slip) and the solid/wall-fluid repulsion (no-penetration).
 *
 * Diagnostics (flap_metrics.h): "flap_crossings", every -flap_crossing_interval
 * steps, and "flap", flap.csv at output times and flap-particles.csv at the end. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/body_force.h"
#include "dmhs/solid_load.h"
#include "flap_metrics.h"
#include "scenes/solid_strip.h"

typedef struct {
  PetscInt nx, ny;    /* liquid lattice (before the flap is cut out) */
  PetscInt flap_x;    /* lattice column of the flap's upstream layer */
  PetscInt flap_rows; /* flap rows above the wall */
  double dx, solid_density_ratio;
  solid_strip st;
  module *body, *rep;
  PetscInt n_fluid;           /* fluid gids are 0 .. n_fluid-1 */
  PetscInt crossing_interval; /* steps between crossing checks */
} flap_data;

static PetscErrorCode flap_set_from_options(scene *self, sim *s) {
  flap_data *f = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene flap (flexible flap in a periodic channel flow)", NULL);
  PetscCall(options_read_int("-flap_nx", "Liquid lattice columns (periodic length = nx dx) [1]",
                             NULL, f->nx, &f->nx, NULL));
  PetscCall(options_read_int("-flap_ny", "Liquid lattice rows (channel width = ny dx) [1]", NULL,
                             f->ny, &f->ny, NULL));
  PetscCall(options_read_real("-flap_dx",
                              "Particle spacing dx [m] (also the flap's bond rest length)", NULL,
                              f->dx, &f->dx, NULL));
  PetscCall(options_read_int("-flap_rows", "Flap height in rows above the wall [1]", NULL,
                             f->flap_rows, &f->flap_rows, NULL));
  PetscCall(options_read_int("-flap_column", "Lattice column of the flap's upstream layer [1]",
                             NULL, f->flap_x, &f->flap_x, NULL));
  PetscCall(options_read_real("-flap_density_ratio",
                              "Flap particle mass / liquid particle mass [1]", NULL,
                              f->solid_density_ratio, &f->solid_density_ratio, NULL));
  PetscCall(options_read_int("-flap_crossing_interval",
                             "Steps between checks that no liquid crosses the flap [1]", NULL,
                             f->crossing_interval, &f->crossing_interval, NULL));
  PetscOptionsEnd();
  PetscCheck(f->crossing_interval >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_crossing_interval must be >= 1 (got %" PetscInt_FMT ")", f->crossing_interval);
  PetscCheck(f->nx > 4, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_nx must be > 4 (got %" PetscInt_FMT ")", f->nx);
  PetscCheck(f->ny > 4, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_ny must be > 4 (got %" PetscInt_FMT ")", f->ny);
  PetscCheck(f->dx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-flap_dx must be > 0 m (got %g)",
             f->dx);
  PetscCheck(f->flap_rows >= 2 && f->flap_rows < f->ny - 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_rows must lie in [2, %" PetscInt_FMT "] (-flap_ny - 3; got %" PetscInt_FMT ")",
             f->ny - 3, f->flap_rows);
  PetscCheck(f->flap_x >= 0 && f->flap_x + 1 < f->nx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_column must lie in [0, %" PetscInt_FMT "] (-flap_nx - 2; got %" PetscInt_FMT
             ")",
             f->nx - 2, f->flap_x);
  PetscCheck(f->solid_density_ratio > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_density_ratio must be > 0 (got %g)", f->solid_density_ratio);
  s->dx = f->dx;
  /* A viscous liquid so that the flow settles in a short run (override with -sph_*).
   * c0: the flap carries most of the drive, F ~ rho g (channel area), as a
   * pressure jump dp ~ F/L of a few Pa across it; Tait liquid cannot hold a
   * tension below -B = -c0^2 rho0/7 (1.4 Pa at c0 = 0.1 m/s: a void opened
   * behind the tip and the density varied 20 %). c0 = 1 m/s gives B = 143 Pa,
   * density variations ~1 %, and costs nothing: dt is set by the bonds. */
  module *sph;
  PetscCall(fields_enable("x0")); /* the flap's particle CSV: displacements */
  PetscCall(modules_enable(s, "sph", &sph));
  PetscCall(sph_set_liquid(sph, 2.5 * f->dx, 1000.0, 1.0, 1e-4)); /* h, rho0, c0, nu */
  PetscCall(modules_enable(s, "body_force", &f->body));
  PetscCall(body_force_set_default(f->body, 0.5, 0.0));
  PetscCall(solid_modules_enable(s, BOND_HARMONIC));
  /* a soft flap: EI = K dx^3 + 2 k_a dx (doc/theory.md) */
  PetscCall(bond_set_default(s, 2e3, f->dx, 0.5 * f->dx));
  PetscCall(angle_set_default(s, 1e-5, 90.0));
  PetscCall(modules_enable(s, "repulsion", &f->rep));
  PetscCall(repulsion_set_default(f->rep, 1e-6, f->dx, 4, 2));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  flap_data *f = self->data;
  const double dx = f->dx, m = sp->rho0 * dx * dx, zero[2] = {0, 0};
  const PetscInt layers = (PetscInt)ceil(sp->h / dx - 1e-9);
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  s->dom.lo[0] = 0;
  s->dom.hi[0] = f->nx * dx;
  s->dom.periodic[0] = PETSC_TRUE;
  s->dom.lo[1] = -layers * dx;
  s->dom.hi[1] = (f->ny + layers) * dx;
  s->dom.periodic[1] = PETSC_FALSE;
  /* liquid first (gids 0 .. n_fluid-1), minus the flap's sites */
  for (PetscInt j = 0; j < f->ny; j++)
    for (PetscInt i = 0; i < f->nx; i++) {
      if ((i == f->flap_x || i == f->flap_x + 1) && j < f->flap_rows)
        continue;
      const double x[2] = {(i + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, zero, m, sp->rho0, NULL));
    }
  f->n_fluid = gid;
  /* walls; the flap's clamped row replaces the top lower-wall layer at its columns */
  for (PetscInt k = 0; k < layers; k++)
    for (PetscInt i = 0; i < f->nx; i++) {
      const double below[2] = {(i + 0.5) * dx, -(k + 0.5) * dx},
                   above[2] = {(i + 0.5) * dx, (f->ny + k + 0.5) * dx};
      if (!(k == 0 && (i == f->flap_x || i == f->flap_x + 1)))
        PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, below, zero, m, sp->rho0, NULL));
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, above, zero, m, sp->rho0, NULL));
    }
  /* the flap: columns of the strip run up the channel, layer 0 upstream */
  bond_style style;
  const bond_params *bp;
  PetscCall(bond_get_params(s, &style, &bp));
  PetscCheck(
      fabs(bp->r0[0] - dx) <= 1e-9 * dx, s->comm, PETSC_ERR_ARG_INCOMP,
      "flap: -bond_r0 (%g m) must equal -flap_dx (%g m): the flap sits on the liquid's lattice",
      bp->r0[0], dx);
  f->st.n = f->flap_rows + 1;
  f->st.n_clamp = 1;
  f->st.origin[0] = (f->flap_x + 0.5) * dx;
  f->st.origin[1] = -0.5 * dx;
  f->st.along[0] = 0;
  f->st.along[1] = 1;
  f->st.across[0] = 1;
  f->st.across[1] = 0;
  f->st.spacing = dx;
  f->st.mass = f->solid_density_ratio * m;
  f->st.rho = sp->rho0;
  PetscCall(solid_strip_build(s, &f->st, &gid));
  const flap_layout lay = {.first_gid = f->st.first_gid,
                           .n_rows = f->st.n,
                           .n_clamp = f->st.n_clamp,
                           .height_rows = f->flap_rows,
                           .dx = dx,
                           .n_fluid = f->n_fluid};
  diagnostic *crossings;
  PetscCall(flap_crossings_register(s, &lay, f->crossing_interval, &crossings));
  PetscCall(flap_rows_register(s, &lay, crossings));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode flap_scene_create(scene **out) {
  flap_data *f;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&f));
  f->nx = 40;
  f->ny = 24;
  f->dx = 1e-4;
  f->flap_rows = 10;
  f->flap_x = 12;
  f->solid_density_ratio = 1.0;
  f->crossing_interval = 1;
  (*out)->name = "flap";
  (*out)->set_from_options = flap_set_from_options;
  (*out)->build = flap_build;
  (*out)->destroy = flap_destroy;
  (*out)->data = f;
  PetscFunctionReturn(0);
}
