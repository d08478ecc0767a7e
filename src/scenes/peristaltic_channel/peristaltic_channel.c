/* Scene peristaltic_channel: a channel full of liquid, periodic in x over one
 * wavelength lambda, whose walls y = +-(a + b sin(2 pi (x - c t)/lambda)) move up and
 * down as a travelling wave (module wall_wave), with no pressure rise over the period.
 * At long wavelength and low Reynolds number its time-mean flux is Shapiro, Jaffrin &
 * Weinberg's (analytic.h), which the diagnostic peristaltic_flux compares every wave
 * period with (doc/validation.md).
 *
 * Defaults follow a, so that any one option changed alone is still a sound run: the
 * spacing dx = a/ny, h = 3 dx, the wavelength 40 a (a/lambda = 0.025), the viscosity
 * nu = c a/0.1 (Re = c a/nu = 0.1), and the sound speed
 * c0 = max(20 c, 2 nu/h_s, sqrt(dp/(2 rho0 0.03))), dp the lubrication solution's
 * pressure range: a density deviation of about 3 % and Mach below 0.1 (the liquid
 * moves at up to ~1.5 c). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/modules.h"
#include "dmhs/fields.h"
#include "dmhs/scenes.h"
#include "dmhs/analytic.h"
#include "dmhs/wall_wave.h"
#include "peristaltic_flux.h"

#define PERISTALTIC_RE            0.1  /* default Reynolds number c a/nu */
#define PERISTALTIC_WAVELENGTH_A  40.  /* default lambda/a */
#define PERISTALTIC_RHO_DEV       0.03 /* density deviation the default c0 aims at */
#define PERISTALTIC_MACH_C        20.  /* c0 >= this times c: Mach < 0.1 at speeds up to 5 c */
#define PERISTALTIC_PHI_CORRECTED 0.25 /* corrected operators up to this b/a (held at 0.2) */

typedef struct {
  double a, b, lambda, c; /* half-width, amplitude, wavelength [m], wave speed [m/s] */
  PetscInt ny;            /* liquid particles across the half-width a */
  PetscInt nx;            /* columns along the wavelength */
} peristaltic_data;

static PetscErrorCode peristaltic_set_from_options(scene *self, sim *s) {
  peristaltic_data *c = self->data;
  PetscBool lambda_set, nu_set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene peristaltic_channel", NULL);
  PetscCall(
      options_read_real("-peristaltic_a", "Walls' mean half-width a [m]", NULL, c->a, &c->a, NULL));
  PetscCall(options_read_real("-peristaltic_b", "Wave amplitude b [m], 0 <= b < a", NULL, c->b,
                              &c->b, NULL));
  c->lambda = PERISTALTIC_WAVELENGTH_A * c->a;
  PetscCall(options_read_real("-peristaltic_wavelength",
                              "Wavelength lambda = the x period [m] (default 40 a)", NULL,
                              c->lambda, &c->lambda, &lambda_set));
  PetscCall(options_read_real("-peristaltic_speed", "Wave speed c along +x [m/s]", NULL, c->c,
                              &c->c, NULL));
  PetscCall(options_read_int("-peristaltic_ny",
                             "Liquid particles across the half-width a (spacing dx = a/ny) [1]",
                             NULL, c->ny, &c->ny, NULL));
  PetscOptionsEnd();
  PetscCheck(c->a > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-peristaltic_a must be > 0 (got %g m)",
             c->a);
  PetscCheck(c->b >= 0 && c->b < c->a, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristaltic_b must satisfy 0 <= b < a (got b = %g m with -peristaltic_a %g m)", c->b,
             c->a);
  PetscCheck(c->lambda > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristaltic_wavelength must be > 0 (got %g m)", c->lambda);
  PetscCheck(c->c > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristaltic_speed must be > 0 (got %g m/s)", c->c);
  PetscCheck(c->ny >= 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristaltic_ny must be >= 2 (got %" PetscInt_FMT ")", c->ny);
  s->dx = c->a / (double)c->ny;
  /* the columns tile the period exactly: the channel's volume 2 a lambda is then the
   * liquid's at every time (the sine sums to zero over the columns) */
  const double columns = c->lambda / s->dx;
  c->nx = (PetscInt)llround(columns);
  PetscCheck(c->nx >= 1 && fabs(columns - (double)c->nx) <= 1e-6 * columns, s->comm,
             PETSC_ERR_ARG_INCOMP,
             "-peristaltic_wavelength %g m is not a multiple of the particle spacing dx = a/ny = "
             "%g m (lambda/dx = %.9g)%s",
             c->lambda, s->dx, columns, lambda_set ? "" : " (the default wavelength is 40 a)");
  PetscCheck(
      c->a - c->b >= 0.5 * s->dx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-peristaltic_b %g m leaves a throat a - b = %g m narrower than half the spacing "
      "dx = %g m: no liquid particle would fit; raise -peristaltic_ny or lower the amplitude",
      c->b, c->a - c->b, s->dx);

  /* the liquid: nu from Re, c0 from the lubrication pressure (-sph_nu, if given, counts) */
  double nu = c->c * c->a / PERISTALTIC_RE;
  PetscCall(options_get_real(NULL, NULL, "-sph_nu", &nu, &nu_set));
  const double rho0 = 1000.0;
  const double dp = analytic_peristaltic_pressure_range(c->a, c->b, c->lambda, c->c, rho0 * nu);
  /* and never below 2 nu/h_s, where the sound-speed limit on dt meets the viscous one: a
   * stiffer liquid there costs no step and settles its pressure sooner */
  const double h_s = 1.5 * s->dx;
  const double c0 = PetscMax(PetscMax(PERISTALTIC_MACH_C * c->c, 2.0 * nu / h_s),
                             sqrt(dp / (2.0 * rho0 * PERISTALTIC_RHO_DEV)));
  /* the walls move first, so that every other module's sweep sees them at the wave */
  module *wave, *sph;
  PetscCall(modules_enable(s, "wall_wave", &wave));
  PetscCall(wall_wave_set(wave, c->a, c->b, c->lambda, c->c));
  PetscCall(modules_enable(s, "sph", &sph));
  sph_params *sp = sph_defaults(sph);
  PetscCall(sph_set_liquid(sph, 3.0 * s->dx, rho0, c0, nu)); /* h, rho0, c0, nu */
  /* the lubrication profile is a parabola across the channel: the quadratic no-slip
   * extrapolation is exact for it */
  sp->wall = SPH_WALL_QUADRATIC;
  /* a shallow wave with a wide throat keeps the second-order interior the quadratic walls
   * want (the corrected operators, blind to a uniform pressure). A deeper wave's suction
   * side pulls harder, and there its negative pressure let the liquid through the walls:
   * phi = 0.8 at ny = 4 (throat 0.8 dx) after a third of a period, phi = 0.5 at ny = 8
   * (throat 4 dx, full support) after half a period; phi = 0.2 at ny = 4 held. The
   * symmetric form with a background pressure of the lubrication range keeps every
   * pressure positive: it ran both of those through (doc/validation.md) */
  const PetscBool corrected = c->b <= PERISTALTIC_PHI_CORRECTED * c->a && c->a - c->b >= 2.5 * s->dx
                                  ? PETSC_TRUE
                                  : PETSC_FALSE;
  sp->kernel_correction = corrected;
  sp->p_background = corrected ? 0.0 : dp;
  /* density diffusion: without it the narrow throat of a deep wave tears the liquid */
  sp->delta = 0.02;
  PetscCall(fields_enable("to_surface"));       /* kept on the moving surface by wall_wave */
  sim_default_t_end(s, 2.0 * c->lambda / c->c); /* two wave periods */
  PetscFunctionReturn(0);
}

static PetscErrorCode peristaltic_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  peristaltic_data *c = self->data;
  const double dx = s->dx, zero[DMHS_DIM] = {0, 0};
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  /* enough wall rows to cover the kernel support of the liquid next to them */
  const PetscInt layers = (PetscInt)ceil(sp->h / dx - 1e-9);
  s->dom.lo[0] = 0;
  s->dom.hi[0] = c->lambda;
  s->dom.periodic[0] = PETSC_TRUE;
  s->dom.hi[1] = c->a + c->b + layers * dx;
  s->dom.lo[1] = -s->dom.hi[1];
  s->dom.periodic[1] = PETSC_FALSE;
  PetscCall(
      particles_reserve(&s->ps, c->nx * (2 * (c->ny + (PetscInt)ceil(c->b / dx)) + 2 * layers)));
  /* the liquid at t = 0: each column filled from wall to wall with equal rows, whose
   * masses make up exactly the column's volume at rho0 */
  for (PetscInt i = 0; i < c->nx; i++) {
    const double x = (i + 0.5) * dx, h = c->a + c->b * sin(2.0 * M_PI * x / c->lambda);
    const PetscInt n = PetscMax(1, (PetscInt)llround(2.0 * h / dx));
    const double dy = 2.0 * h / (double)n;
    for (PetscInt j = 0; j < n; j++) {
      const double p[DMHS_DIM] = {x, -h + (j + 0.5) * dy};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, p, zero, sp->rho0 * dx * dy,
                                    sp->rho0, NULL));
    }
  }
  /* the walls: columns of rows below and above the surfaces, rest positions (x0) those of
   * the flat channel y = +-a, which wall_wave moves to the wave */
  for (PetscInt k = 0; k < layers; k++)
    for (PetscInt i = 0; i < c->nx; i++) {
      const double x = (i + 0.5) * dx, h = c->a + c->b * sin(2.0 * M_PI * x / c->lambda);
      const double depth = (k + 0.5) * dx;
      for (int side = -1; side <= 1; side += 2) {
        const double p[DMHS_DIM] = {x, side * (h + depth)};
        PetscInt row;
        PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, p, zero, sp->rho0 * dx * dx,
                                      sp->rho0, &row));
        s->ps.x0[row][0] = x;
        s->ps.x0[row][1] = side * (c->a + depth);
        s->ps.to_surface[row][0] = 0.0;
        s->ps.to_surface[row][1] = -side * depth;
      }
    }
  const peristaltic_flux_layout lay = {.a = c->a, .b = c->b, .lambda = c->lambda, .c = c->c};
  PetscCall(peristaltic_flux_register(s, &lay));
  PetscFunctionReturn(0);
}

static PetscErrorCode peristaltic_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode peristaltic_channel_scene_create(scene **out) {
  peristaltic_data *c;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&c));
  c->a = 1e-3;
  c->b = 0.5e-3;
  c->c = 1e-3;
  c->ny = 4;
  (*out)->name = "peristaltic_channel";
  (*out)->set_from_options = peristaltic_set_from_options;
  (*out)->build = peristaltic_build;
  (*out)->destroy = peristaltic_destroy;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
