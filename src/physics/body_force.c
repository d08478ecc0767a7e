/* Body force on liquid particles (and, with -body_force_types fluid,solid, on
 * the solids too: a membrane's weight under gravity):
 *   a_body(t) = F                         (-body_force_period 0)
 *   a_body(t) = F sin(2 pi t / T)          (-body_force_period T > 0)
 * plus gravity (0, -g). -body_force_amplitude g0 is F = (g0, 0), the pulsatile
 * drive g0 sin(2 pi t/T) of the vein case (doc/cases.md). Its prepare phase evaluates the
 * value at the force evaluation's time before any module computes, so that the wall pass
 * (sph.c) reads the current value (body_force_current) for the hydrostatic part of the wall
 * pressure. */
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/body_force.h"
#include "dmhs/events.h"

typedef struct {
  double F[DMHS_DIM];             /* [m/s^2] */
  double period;                  /* [s], 0 = constant */
  double gravity;                 /* [m/s^2], along -y */
  PetscBool on_type[PTYPE_COUNT]; /* which particle types feel it (walls never: their motion is
                                     prescribed) */
  double current[DMHS_DIM];       /* a_body at the time of the last prepare [m/s^2] */
} body_force_data;

static const char *const body_force_type_names[PTYPE_COUNT] = {"fluid", "wall", "solid", "clot"};

PetscErrorCode body_force_set_default(module *m, double fx, double fy) {
  body_force_data *d = m->data;
  PetscFunctionBeginUser;
  d->F[0] = fx;
  d->F[1] = fy;
  PetscFunctionReturn(0);
}

PetscErrorCode body_force_get(module *m, double F[DMHS_DIM], double *period) {
  const body_force_data *d = m->data;
  PetscFunctionBeginUser;
  PetscCheck(d && !strcmp(m->name, "body_force"), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "body_force_get: module %s is not body_force", m->name);
  if (F)
    for (int k = 0; k < DMHS_DIM; k++)
      F[k] = d->F[k];
  if (period)
    *period = d->period;
  PetscFunctionReturn(0);
}

PetscErrorCode body_force_set_default_gravity(module *m, double g) {
  body_force_data *d = m->data;
  PetscFunctionBeginUser;
  d->gravity = g;
  PetscFunctionReturn(0);
}

PetscErrorCode body_force_set_default_period(module *m, double period) {
  body_force_data *d = m->data;
  PetscFunctionBeginUser;
  d->period = period;
  PetscFunctionReturn(0);
}

static void body_force_value(const body_force_data *d, double t, double a[DMHS_DIM]) {
  const double phase = d->period > 0 ? sin(2.0 * M_PI * t / d->period) : 1.0;
  a[0] = d->F[0] * phase;
  a[1] = d->F[1] * phase - d->gravity;
}

static PetscErrorCode body_force_set_from_options(module *self, sim *s) {
  body_force_data *d = self->data;
  PetscInt n = DMHS_DIM;
  PetscBool set, set_amplitude;
  double amplitude = d->F[0];
  char *types[PTYPE_COUNT] = {NULL};
  PetscInt n_types = PTYPE_COUNT;
  PetscBool set_types;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Body force on the liquid (module body_force)", NULL);
  PetscCall(options_read_real_array("-body_force", "Body acceleration Fx,Fy [m/s^2]", NULL, d->F,
                                    &n, &set));
  PetscCall(options_read_real("-body_force_amplitude",
                              "Drive amplitude g0 along x [m/s^2]: g0 sin(2 pi t/T) with "
                              "-body_force_period T, else constant "
                              "(same as -body_force g0,0)",
                              NULL, amplitude, &amplitude, &set_amplitude));
  PetscCall(options_read_real("-body_force_period",
                              "Period T of F sin(2 pi t/T) [s] (0 = constant)", NULL, d->period,
                              &d->period, NULL));
  PetscCall(options_read_real("-gravity", "Gravity along -y [m/s^2]", NULL, d->gravity, &d->gravity,
                              NULL));
  PetscCall(options_read_string_array(
      "-body_force_types", "Particle types the body force acts on: fluid, solid, clot [1]", NULL,
      types, &n_types, &set_types));
  PetscOptionsEnd();
  if (set_types) {
    for (int t = 0; t < PTYPE_COUNT; t++)
      d->on_type[t] = PETSC_FALSE;
    for (PetscInt k = 0; k < n_types; k++) {
      int found = -1;
      for (int t = 0; t < PTYPE_COUNT; t++)
        if (!strcmp(types[k], body_force_type_names[t]))
          found = t;
      PetscCheck(found >= 0 && found != PTYPE_WALL, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
                 "-body_force_types: '%s' is not fluid or solid or clot (walls move as prescribed)",
                 types[k]);
      d->on_type[found] = PETSC_TRUE;
    }
  }
  if (set_types)
    for (PetscInt k = 0; k < n_types; k++)
      PetscCall(PetscFree(types[k]));
  PetscCheck(!(set && set_amplitude), s->comm, PETSC_ERR_ARG_INCOMP,
             "give either -body_force Fx,Fy or -body_force_amplitude g0 (along x), not both");
  if (set_amplitude) {
    d->F[0] = amplitude;
    d->F[1] = 0;
  }
  PetscCheck(!set || n == DMHS_DIM, s->comm, PETSC_ERR_ARG_SIZ,
             "-body_force takes %d components Fx,Fy (got %d)", DMHS_DIM, (int)n);
  PetscCheck(d->period >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-body_force_period must be >= 0 (got %g)", d->period);
  body_force_value(d, 0.0, d->current);
  PetscFunctionReturn(0);
}

void body_force_current(const module *m, double a[DMHS_DIM]) {
  const body_force_data *d = m->data;
  a[0] = d->current[0];
  a[1] = d->current[1];
}

void body_force_at(const module *m, double t, double a[DMHS_DIM]) {
  body_force_value(m->data, t, a);
}

static PetscErrorCode body_force_prepare(module *self, sim *s) {
  body_force_data *d = self->data;
  PetscFunctionBeginUser;
  body_force_value(d, s->t, d->current);
  PetscFunctionReturn(0);
}

static PetscErrorCode body_force_compute(module *self, sim *s) {
  body_force_data *d = self->data;
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.body_force, 0, 0, 0, 0));
  const double ax = d->current[0], ay = d->current[1];
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (!d->on_type[ps->type[i]])
      continue;
    ps->a[i][0] += ax;
    ps->a[i][1] += ay;
  }
  PetscCall(PetscLogEventEnd(events.body_force, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

double body_force_peak(const module *m) {
  const body_force_data *d = m->data;
  const double ay = PetscAbsReal(d->F[1]) + d->gravity;
  return PetscSqrtReal(d->F[0] * d->F[0] + ay * ay);
}

static PetscErrorCode body_force_view(module *self, sim *s, PetscViewer v) {
  body_force_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(
      v, "body_force: F = (%g, %g) m/s^2, period %g s%s, gravity %g m/s^2, on %s%s%s\n", d->F[0],
      d->F[1], d->period, d->period > 0 ? "" : " (constant)", d->gravity,
      d->on_type[PTYPE_FLUID] ? "fluid " : "", d->on_type[PTYPE_SOLID] ? "solid" : "",
      d->on_type[PTYPE_CLOT] ? " clot" : ""));
  PetscFunctionReturn(0);
}

static PetscErrorCode body_force_destroy(module *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode body_force_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "body_force";
  (*m)->set_from_options = body_force_set_from_options;
  (*m)->prepare = body_force_prepare;
  (*m)->compute = body_force_compute;
  (*m)->view = body_force_view;
  (*m)->destroy = body_force_destroy;
  PetscCall(PetscNew((body_force_data **)&(*m)->data));
  ((body_force_data *)(*m)->data)->on_type[PTYPE_FLUID] =
      PETSC_TRUE; /* the liquid only, by default */
  PetscFunctionReturn(0);
}
