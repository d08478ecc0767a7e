/* Plane channel (doc/cases.md): nx x ny liquid particles on a square lattice of
 * spacing dx = l/ny between wall layers, periodic in x. The lower wall is at
 * rest; the upper one moves at -wall_speed (Couette). Poiseuille flow is driven
 * by the body force module: constant (start-up Poiseuille) or, with
 * -body_force_period T > 0, pulsatile g0 sin(2 pi t/T) (Womersley start-up).
 * The liquid's v_x is compared with the series solution as the run goes
 * (the diagnostic "errors", diag/errors.c). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/modules.h"
#include "dmhs/fields.h"
#include "dmhs/channel.h"
#include "dmhs/analytic.h"
#include "dmhs/errors.h"
#include "dmhs/body_force.h"

typedef struct {
  channel_flow flow;
  double width, length; /* l (wall to wall) and the x period [m] */
  PetscInt nx, ny;
  PetscInt wall_layers; /* 0 = enough to fill the kernel support */
  double wall_speed;    /* upper plate (Couette) [m/s] */
  double drive;         /* F or g0 (Poiseuille) [m/s^2], read back from the body force module */
  double omega;         /* 2 pi/T of a pulsatile drive [1/s], 0 = constant */
  double nu;            /* for the exact solution */
  module *body;
  errors_times report_times; /* of the diagnostic "errors" */
} channel_data;

static double exact_poiseuille(double y, double t, const void *ctx) {
  const channel_data *c = ctx;
  return analytic_poiseuille(y, t, c->drive, c->nu, c->width);
}

static double exact_womersley(double y, double t, const void *ctx) {
  const channel_data *c = ctx;
  return analytic_womersley(y, t, c->drive, c->omega, c->nu, c->width);
}

static double exact_couette(double y, double t, const void *ctx) {
  const channel_data *c = ctx;
  return analytic_couette(y, t, c->wall_speed, c->nu, c->width);
}

static PetscErrorCode channel_set_from_options(scene *self, sim *s) {
  channel_data *c = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL,
                    c->flow == CHANNEL_POISEUILLE ? "Scene poiseuille" : "Scene couette", NULL);
  PetscCall(options_read_real("-channel_width", "Distance l between the walls [m]", NULL, c->width,
                              &c->width, NULL));
  PetscCall(options_read_real("-channel_length", "Periodic length along x [m]", NULL, c->length,
                              &c->length, NULL));
  PetscCall(
      options_read_int("-channel_nx", "Liquid particles along x [1]", NULL, c->nx, &c->nx, NULL));
  PetscCall(options_read_int("-channel_ny", "Liquid particles across the channel [1]", NULL, c->ny,
                             &c->ny, NULL));
  PetscCall(options_read_int("-channel_wall_layers",
                             "Wall particle layers per wall [1] (0 = fill the support)", NULL,
                             c->wall_layers, &c->wall_layers, NULL));
  if (c->flow == CHANNEL_COUETTE)
    PetscCall(options_read_real("-wall_speed", "Upper plate speed along x [m/s]", NULL,
                                c->wall_speed, &c->wall_speed, NULL));
  PetscOptionsEnd();
  PetscCheck(c->width > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-channel_width must be > 0 m (got %g)", c->width);
  PetscCheck(c->length > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-channel_length must be > 0 m (got %g)", c->length);
  PetscCheck(c->nx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-channel_nx must be > 0 (got %" PetscInt_FMT ")", c->nx);
  PetscCheck(c->ny > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-channel_ny must be > 0 (got %" PetscInt_FMT ")", c->ny);
  PetscCheck(c->wall_layers >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-channel_wall_layers must be >= 0 (got %" PetscInt_FMT ")", c->wall_layers);
  s->dx = c->width / (double)c->ny;
  const double dx_along = c->length / (double)c->nx;
  PetscCheck(fabs(dx_along - s->dx) <= 1e-9 * s->dx, s->comm, PETSC_ERR_ARG_INCOMP,
             "the lattice must be square: -channel_length/-channel_nx = %g m but "
             "-channel_width/-channel_ny = %g m",
             dx_along, s->dx);

  /* the published channel setup; every value can be overridden with -sph_* */
  module *sph;
  PetscCall(modules_enable(s, "sph", &sph));
  sph_params *sp = sph_defaults(sph);
  PetscCall(sph_set_liquid(sph, 3.0 * s->dx, 1000.0, 0.01, 1e-6)); /* h, rho0, c0, nu */
  /* steady flows run for seconds to minutes: plain SPH sums drift with the
   * sheared lattice's arrangement, and a second-order interior needs a
   * second-order wall (doc/theory.md, "Long-time accuracy") */
  sp->kernel_correction = PETSC_TRUE;
  sp->wall = SPH_WALL_QUADRATIC;
  /* the walls' geometry (for -sph_wall_extrapolation quadratic; the module's
   * options are read after the scene's, so it is provided whatever they say) */
  PetscCall(fields_enable("to_surface"));
  if (c->flow == CHANNEL_POISEUILLE) {
    PetscCall(modules_enable(s, "body_force", &c->body));
    PetscCall(body_force_set_default(c->body, 2e-4, 0.0));
  }
  PetscCall(errors_set_from_options(&c->report_times, s));
  PetscFunctionReturn(0);
}

static PetscErrorCode channel_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  channel_data *c = self->data;
  const double dx = s->dx, m = sp->rho0 * dx * dx;
  const double zero[DMHS_DIM] = {0, 0}, plate[DMHS_DIM] = {c->wall_speed, 0};
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  const PetscInt layers = c->wall_layers > 0 ? c->wall_layers : (PetscInt)ceil(sp->h / dx - 1e-9);
  s->dom.lo[0] = 0;
  s->dom.hi[0] = c->length;
  s->dom.periodic[0] = PETSC_TRUE;
  s->dom.lo[1] = -layers * dx;
  s->dom.hi[1] = c->width + layers * dx;
  s->dom.periodic[1] = PETSC_FALSE;
  PetscCall(particles_reserve(&s->ps, c->nx * (c->ny + 2 * layers)));
  for (PetscInt j = 0; j < c->ny; j++)
    for (PetscInt i = 0; i < c->nx; i++) {
      const double x[DMHS_DIM] = {(i + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, zero, m, sp->rho0, NULL));
    }
  for (PetscInt k = 0; k < layers; k++)
    for (PetscInt i = 0; i < c->nx; i++) {
      const double below[DMHS_DIM] = {(i + 0.5) * dx, -(k + 0.5) * dx};
      const double above[DMHS_DIM] = {(i + 0.5) * dx, c->width + (k + 0.5) * dx};
      PetscInt lo, hi;
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, below, zero, m, sp->rho0, &lo));
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, above, plate, m, sp->rho0, &hi));
      /* the surfaces are y = 0 and y = l */
      s->ps.to_surface[lo][0] = s->ps.to_surface[hi][0] = 0.0;
      s->ps.to_surface[lo][1] = (k + 0.5) * dx;
      s->ps.to_surface[hi][1] = -(k + 0.5) * dx;
    }
  c->nu = sp->nu;
  if (c->flow == CHANNEL_POISEUILLE) {
    double F[DMHS_DIM], period;
    PetscCall(body_force_get(c->body, F, &period));
    PetscCheck(c->nu > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "poiseuille: -sph_nu must be > 0 for the series solution (got %g)", c->nu);
    if (period > 0) {
      /* a pulsatile flow passes through zero: the error is normalised by the fixed
       * steady-periodic centreline amplitude */
      c->drive = F[0];
      c->omega = 2.0 * M_PI / period;
      PetscCheck(c->drive != 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
                 "poiseuille: with -body_force_period %g s the drive along x is 0: set "
                 "-body_force_amplitude g0 (or -body_force g0,0)",
                 period);
      PetscCall(errors_register(s, &c->report_times, exact_womersley, c,
                                analytic_womersley_amplitude(c->drive, c->omega, c->nu, c->width)));
    } else {
      c->drive = F[0];
      const double peak = c->drive * c->width * c->width / (8.0 * c->nu);
      PetscCall(errors_register(s, &c->report_times, exact_poiseuille, c, peak));
    }
  } else {
    PetscCall(errors_register(s, &c->report_times, exact_couette, c, fabs(c->wall_speed)));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode channel_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode channel_scene_create(channel_flow flow, scene **out) {
  channel_data *c;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&c));
  c->flow = flow;
  c->width = 1e-3;
  c->length = 5e-4;
  c->nx = 40;
  c->ny = 80;
  c->wall_speed = flow == CHANNEL_COUETTE ? 2.5e-5 : 0.0;
  (*out)->name = flow == CHANNEL_POISEUILLE ? "poiseuille" : "couette";
  (*out)->set_from_options = channel_set_from_options;
  (*out)->build = channel_build;
  (*out)->destroy = channel_destroy;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
