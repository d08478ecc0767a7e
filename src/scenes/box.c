/* Scene box: a doubly periodic square of liquid, the benchmark case. Particles
 * start on a square lattice with a Taylor-Green vortex velocity
 *   u =  U sin(2 pi x/L) cos(2 pi y/L),  v = -U cos(2 pi x/L) sin(2 pi y/L)
 * so that every pass of the solver does real work. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"

typedef struct {
  PetscInt nx, ny;
  double dx;       /* lattice spacing [m] */
  double velocity; /* vortex amplitude U [m/s] */
} box_data;

static PetscErrorCode box_set_from_options(scene *self, sim *s) {
  box_data *b = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene box", NULL);
  PetscCall(options_read_int("-box_nx", "Particles along x [1]", NULL, b->nx, &b->nx, NULL));
  PetscCall(options_read_int("-box_ny", "Particles along y [1]", NULL, b->ny, &b->ny, NULL));
  PetscCall(options_read_real("-box_dx", "Lattice spacing [m]", NULL, b->dx, &b->dx, NULL));
  PetscCall(options_read_real("-box_velocity", "Taylor-Green vortex amplitude U [m/s]", NULL,
                              b->velocity, &b->velocity, NULL));
  PetscOptionsEnd();
  PetscCheck(b->nx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-box_nx must be > 0 (got %" PetscInt_FMT ")", b->nx);
  PetscCheck(b->ny > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-box_ny must be > 0 (got %" PetscInt_FMT ")", b->ny);
  PetscCheck(b->dx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-box_dx must be > 0 m (got %g)", b->dx);
  s->dx = b->dx;
  /* the vein case's liquid (doc/cases.md) */
  module *sph;
  PetscCall(modules_enable(s, "sph", &sph));
  PetscCall(sph_set_liquid(sph, 2.5 * b->dx, 1056.0, 10.0, 3.3e-6)); /* h, rho0, c0, nu */
  PetscCall(sph_set_no_walls(sph)); /* a periodic box of liquid: no v_visc field */
  PetscFunctionReturn(0);
}

static PetscErrorCode box_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  box_data *b = self->data;
  const double Lx = b->nx * b->dx, Ly = b->ny * b->dx, m = sp->rho0 * b->dx * b->dx;
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  s->dom.lo[0] = s->dom.lo[1] = 0;
  s->dom.hi[0] = Lx;
  s->dom.hi[1] = Ly;
  s->dom.periodic[0] = s->dom.periodic[1] = PETSC_TRUE;
  PetscCall(particles_reserve(&s->ps, b->nx * b->ny));
  for (PetscInt j = 0; j < b->ny; j++)
    for (PetscInt i = 0; i < b->nx; i++) {
      const double x[DMHS_DIM] = {(i + 0.5) * b->dx, (j + 0.5) * b->dx};
      const double kx = 2 * M_PI * x[0] / Lx, ky = 2 * M_PI * x[1] / Ly;
      const double v[DMHS_DIM] = {b->velocity * sin(kx) * cos(ky),
                                  -b->velocity * cos(kx) * sin(ky)};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, v, m, sp->rho0, NULL));
    }
  PetscFunctionReturn(0);
}

static PetscErrorCode box_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode box_scene_create(scene **out) {
  box_data *b;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&b));
  b->nx = b->ny = 100;
  b->dx = 1e-4;
  b->velocity = 0.01;
  (*out)->name = "box";
  (*out)->set_from_options = box_set_from_options;
  (*out)->build = box_build;
  (*out)->destroy = box_destroy;
  (*out)->data = b;
  PetscFunctionReturn(0);
}
