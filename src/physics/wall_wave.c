/* Module wall_wave (wall_wave.h): the travelling wave of the peristaltic channel's
 * walls, prescribed rather than integrated.
 *
 * Why in prepare: the integrator drifts walls with their velocity (x += dt v,
 * integrate.c), which for a wall whose velocity changes in time lands it a distance
 * dt^2/2 |d^2h/dt^2| off the wave and lets the error of v lag by dt; setting position
 * and velocity from the wave at the evaluation's own time makes the force sweep see
 * the walls exactly where the wave has them, every step, whatever dt was. The offsets
 * from the integrator's drift are O(dt^2), far inside the neighbour lists' skin.
 * The ghost copies of the walls are then refreshed from their owners (x, v, v_est),
 * so every rank sees the same values bit for bit.
 * The Adami wall pressure takes the walls' acceleration as zero (sph_wall.c); here it
 * is b (2 pi c/lambda)^2 at most, whose pressure over the kernel support is a fraction
 * Re phi (2 pi a/lambda)^3 of the lubrication pressure and is left out. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/halo.h"
#include "dmhs/wall_wave.h"

typedef struct {
  double a, b, lambda, c; /* half-width, amplitude, wavelength [m], wave speed [m/s] */
  PetscInt n_wall;        /* wall particles over all ranks */
} wall_wave_data;

PetscErrorCode wall_wave_set(module *m, double a, double b, double lambda, double c) {
  wall_wave_data *d = m->data;
  PetscFunctionBeginUser;
  d->a = a;
  d->b = b;
  d->lambda = lambda;
  d->c = c;
  PetscFunctionReturn(0);
}

static PetscErrorCode wall_wave_set_from_options(module *self, sim *s) {
  const wall_wave_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCheck(d->a > 0 && d->lambda > 0, s->comm, PETSC_ERR_ORDER,
             "wall_wave: the scene must call wall_wave_set");
  PetscCall(fields_enable("x0")); /* the walls' rest positions */
  PetscFunctionReturn(0);
}

/* Every owned wall particle at the wave's position and velocity at time t, then the ghosts
 * from their owners. Collective. */
static PetscErrorCode wall_wave_place(module *self, sim *s) {
  static const char *const moved[] = {"x", "v", "v_est"};
  const wall_wave_data *d = self->data;
  particles *ps = &s->ps;
  const double k = 2.0 * M_PI / d->lambda, t = s->t;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_WALL)
      continue;
    const double y0 = ps->x0[i][1], side = y0 > 0 ? 1.0 : -1.0;
    const double phase = k * (ps->x0[i][0] - d->c * t), sn = sin(phase), cs = cos(phase);
    ps->x[i][0] = ps->x0[i][0];
    ps->x[i][1] = y0 + side * d->b * sn;
    ps->v[i][0] = ps->v_est[i][0] = 0.0;
    ps->v[i][1] = ps->v_est[i][1] = -side * d->b * k * d->c * cs;
    if (ps->to_surface) {
      /* the surface y = side h(x) seen from the particle at depth eta below it: along the
       * normal into the liquid, (h_x, -side)/sqrt(1 + h_x^2), at the tangent's distance */
      const double depth = fabs(y0) - d->a, slope = d->b * k * cs, norm2 = 1.0 + slope * slope;
      ps->to_surface[i][0] = depth * slope / norm2;
      ps->to_surface[i][1] = -side * depth / norm2;
    }
  }
  PetscCall(halo_forward(&s->hal, ps, moved, 3));
  PetscFunctionReturn(0);
}

static PetscErrorCode wall_wave_setup(module *self, sim *s) {
  wall_wave_data *d = self->data;
  PetscInt local = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    local += s->ps.type[i] == PTYPE_WALL;
  PetscCallMPI(MPI_Allreduce(&local, &d->n_wall, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode wall_wave_prepare(module *self, sim *s) {
  PetscFunctionBeginUser;
  PetscCall(wall_wave_place(self, s));
  PetscFunctionReturn(0);
}

/* no force of its own: the walls' motion is prescribed in prepare */
static PetscErrorCode wall_wave_compute(module *self, sim *s) {
  PetscFunctionBeginUser;
  (void)self;
  (void)s;
  PetscFunctionReturn(0);
}

static PetscErrorCode wall_wave_view(module *self, sim *s, PetscViewer v) {
  const wall_wave_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "wall_wave: %" PetscInt_FMT
                                   " wall particles on y = +-(a + b sin(2 pi (x - c t)/lambda)), "
                                   "a = %g m, b = %g m, lambda = %g m, c = %g m/s (period %g s)\n",
                                   d->n_wall, d->a, d->b, d->lambda, d->c, d->lambda / d->c));
  PetscFunctionReturn(0);
}

static PetscErrorCode wall_wave_destroy(module *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode wall_wave_module_create(module **m) {
  wall_wave_data *d;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  PetscCall(PetscNew(&d));
  (*m)->name = "wall_wave";
  (*m)->set_from_options = wall_wave_set_from_options;
  (*m)->setup = wall_wave_setup;
  (*m)->prepare = wall_wave_prepare;
  (*m)->compute = wall_wave_compute;
  (*m)->view = wall_wave_view;
  (*m)->destroy = wall_wave_destroy;
  (*m)->data = d;
  PetscFunctionReturn(0);
}
