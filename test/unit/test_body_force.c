/* Module body_force (src/physics/body_force.c):
 *   a_body(t) = F                  (-body_force_period 0)
 *   a_body(t) = F sin(2 pi t / T)  (-body_force_period T > 0)
 * plus gravity (0, -g), added to the acceleration of the particle types it
 * acts on (fluid by default; never walls); its prepare phase leaves the value at
 * the force evaluation's time for the wall pass (body_force_current). Proves,
 * against values computed here by hand:
 *   - the constant drive with gravity on fluid only, added to what is there;
 *   - the pulsatile drive at quarter, half, three-quarter and an arbitrary
 *     phase; -body_force_amplitude g0 is F = (g0, 0);
 *   - -body_force_types fluid,solid,clot; walls are refused;
 *   - the option errors (F and amplitude together, a negative period, three
 *     components) and the scene defaults (body_force_set_default*, _get);
 *   - the SPH module's time-step limit on it, 0.25 sqrt(0.5 h / |a|max),
 *     |a|max = |(Fx, |Fy| + g)| (body_force_peak), and its scans beside it: the sound-speed
 *     limit takes max|v| over every particle, the acceleration limit max|a| over the liquid
 *     only (a solid's or a wall's larger |a| does not count);
 *   - the two phases of a force evaluation (sim_add_module_forces): a module
 *     enabled before body_force reads, during its compute, the body force at
 *     the evaluation's own time, not the previous evaluation's;
 *   - a first module that sets the rates itself (MODULE_SETS_RATES): the evaluation does not
 *     zero the owned rows' a for it (the ghost rows' still) and body_force adds after it; with that
 * module filtered out, a is zeroed as usual; one that says so and does not set them is an error. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/sph.h"
#include "dmhs/modules.h"
#include "dmhs/body_force.h"
#include "dmhs/registry.h"

static sim s;
static module *m, *sph;

static int setup(void **state) {
  (void)state;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  fields_reset();
  OK(sph_module_create(&sph)); /* the time-step limit reads h */
  sph_defaults(sph)->h = 4e-4;
  OK(particles_create(&s.ps));
  const double x[2] = {0, 0}, v[2] = {0, 0};
  /* one particle of each type, in type order */
  for (int t = 0; t < PTYPE_COUNT; t++)
    OK(particles_add_owned(&s.ps, t, (particle_type)t, x, v, 1.0, 1000.0, NULL));
  OK(body_force_module_create(&m));
  s.modules[0] = sph;
  s.modules[1] = m;
  s.n_modules = 2;
  return 0;
}

static int teardown(void **state) {
  (void)state;
  OK(m->destroy(m));
  OK(PetscFree(m));
  OK(sph->destroy(sph));
  OK(PetscFree(sph));
  OK(particles_destroy(&s.ps));
  OK(PetscOptionsClear(NULL));
  options_forget();
  return 0;
}

/* a of every particle set to (1, 2), then one compute at time t */
static void compute_at(double t) {
  for (PetscInt i = 0; i < s.ps.n_owned; i++) {
    s.ps.a[i][0] = 1.0;
    s.ps.a[i][1] = 2.0;
  }
  s.t = t;
  OK(m->prepare(m, &s));
  OK(m->compute(m, &s));
}

static void assert_current(double ax, double ay, double tol) {
  double a[2];
  body_force_current(m, a);
  assert_close(a[0], ax, tol);
  assert_close(a[1], ay, tol);
}

static void assert_accel(int type, double ax, double ay, double tol) {
  assert_close(s.ps.a[type][0], ax, tol);
  assert_close(s.ps.a[type][1], ay, tol);
}

static void test_constant_with_gravity(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force 0.3,-0.2 -gravity 9.81"));
  OK(m->set_from_options(m, &s));
  /* the options pass already leaves the value at t = 0 */
  assert_current(0.3, -0.2 - 9.81, 1e-15);
  compute_at(0.7);
  assert_accel(PTYPE_FLUID, 1.3, 2.0 - 0.2 - 9.81, 1e-14);
  assert_accel(PTYPE_WALL, 1.0, 2.0, 0);
  assert_accel(PTYPE_SOLID, 1.0, 2.0, 0);
  assert_accel(PTYPE_CLOT, 1.0, 2.0, 0);
  assert_current(0.3, -10.01, 1e-14);
  double F[2], T = -1;
  OK(body_force_get(m, F, &T));
  assert_true(F[0] == 0.3 && F[1] == -0.2 && T == 0.0);
}

static void test_pulsatile(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force_amplitude 2 -body_force_period 0.5"));
  OK(m->set_from_options(m, &s));
  const struct {
    double t, ax;
  } at[] = {{0.0, 0.0},
            {0.125, 2.0},                     /* quarter period: sin(pi/2) = 1 */
            {0.25, 0.0},                      /* half: sin(pi) */
            {0.375, -2.0},                    /* three quarters */
            {0.1, 2.0 * 0.95105651629515357}, /* sin(0.4 pi) */
            {0.625, 2.0}};                    /* a period later: the same as at T/4 */
  for (size_t k = 0; k < sizeof(at) / sizeof(at[0]); k++) {
    compute_at(at[k].t);
    assert_accel(PTYPE_FLUID, 1.0 + at[k].ax, 2.0, 1e-14);
    assert_current(at[k].ax, 0.0, 1e-14);
    double a[2];
    body_force_at(m, at[k].t, a); /* the same value, evaluated at any time */
    assert_close(a[0], at[k].ax, 1e-14);
    assert_accel(PTYPE_SOLID, 1.0, 2.0, 0);
  }
  double F[2], T;
  OK(body_force_get(m, F, &T));
  assert_true(F[0] == 2.0 && F[1] == 0.0 && T == 0.5);
}

static void test_types(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force 0,-1 -body_force_types solid,clot"));
  OK(m->set_from_options(m, &s));
  compute_at(0.0);
  assert_accel(PTYPE_FLUID, 1.0, 2.0, 0); /* the list replaces the default */
  assert_accel(PTYPE_WALL, 1.0, 2.0, 0);
  assert_accel(PTYPE_SOLID, 1.0, 1.0, 0);
  assert_accel(PTYPE_CLOT, 1.0, 1.0, 0);
}

static void test_walls_refused(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force_types fluid,wall"));
  assert_int_equal(m->set_from_options(m, &s), PETSC_ERR_ARG_OUTOFRANGE);
}

static void test_option_errors(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force 1,0 -body_force_amplitude 2"));
  assert_int_equal(m->set_from_options(m, &s), PETSC_ERR_ARG_INCOMP);
  OK(PetscOptionsClear(NULL));
  OK(PetscOptionsInsertString(NULL, "-body_force_period -1"));
  assert_int_equal(m->set_from_options(m, &s), PETSC_ERR_ARG_OUTOFRANGE);
  OK(PetscOptionsClear(NULL));
  OK(PetscOptionsInsertString(NULL, "-body_force 1,0,0"));
  assert_true(m->set_from_options(m, &s) != 0);
}

static void test_scene_defaults(void **state) {
  (void)state;
  double F[2], T;
  OK(body_force_set_default(m, 2e-4, 0.0));
  OK(body_force_set_default_period(m, 0.206));
  OK(m->set_from_options(m, &s)); /* no options: the scene's values stay */
  OK(body_force_get(m, F, &T));
  assert_true(F[0] == 2e-4 && F[1] == 0.0 && T == 0.206);
  compute_at(0.206 / 4);
  assert_accel(PTYPE_FLUID, 1.0 + 2e-4, 2.0, 1e-16);
  OK(body_force_get(m, NULL, NULL));
  /* body_force_get on another module is an error, not a read of its data */
  module *other;
  OK(registry_initialize());
  OK(modules_create("peristalsis", &other));
  assert_int_equal(body_force_get(other, F, &T), PETSC_ERR_ARG_WRONG);
  OK(other->destroy(other));
  OK(PetscFree(other));
  OK(registry_finalize());
}

/* The SPH module's limit of that name, or -1 when it has none. */
static double sph_limit(const char *name) {
  dt_limits l = {0};
  OK(sph->max_dt(sph, &s, &l));
  for (int k = 0; k < l.n; k++)
    if (!strcmp(l.item[k].name, name))
      return l.item[k].value;
  return -1.0;
}

static void test_max_dt(void **state) {
  (void)state;
  sph_defaults(sph)->c0 = 1.0;
  OK(PetscOptionsInsertString(NULL, "-body_force 0.3,-0.2 -gravity 9.81"));
  OK(m->set_from_options(m, &s));
  /* |a|max = sqrt(0.3^2 + (0.2 + 9.81)^2) */
  const double amax = sqrt(0.09 + 10.01 * 10.01), want = 0.25 * sqrt(0.5 * 4e-4 / amax);
  assert_close(body_force_peak(m), amax, 1e-15);
  const double got = sph_limit("body force");
  assert_true(got <= want && got >= want * (1.0 - 0x1p-23)); /* limits are rounded down */
  /* no drive, no gravity: no limit */
  OK(PetscOptionsClear(NULL));
  OK(PetscOptionsInsertString(NULL, "-body_force 0,0 -gravity 0"));
  OK(m->set_from_options(m, &s));
  assert_true(body_force_peak(m) == 0.0);
  assert_true(sph_limit("body force") == -1.0);
}

static void test_sph_speed_scans(void **state) {
  (void)state;
  sph_defaults(sph)->c0 = 10.0;
  const double v[PTYPE_COUNT][2] = {{3, 4}, {0, -6}, {1, 1}, {0, 2}};    /* max |v| 6: a wall */
  const double a[PTYPE_COUNT][2] = {{0, -8}, {90, 0}, {0, 70}, {50, 0}}; /* the liquid's: 8 */
  for (int t = 0; t < PTYPE_COUNT; t++)
    for (int k = 0; k < 2; k++) {
      s.ps.v[t][k] = v[t][k];
      s.ps.a[t][k] = a[t][k];
    }
  const double hs = 0.5 * 4e-4, sound = 0.25 * hs / (10.0 + 6.0), accel = 0.25 * sqrt(hs / 8.0);
  const double got_sound = sph_limit("sph sound speed"), got_accel = sph_limit("sph acceleration");
  /* limits are rounded down to 2^-24 relative */
  assert_true(got_sound <= sound && got_sound >= sound * (1.0 - 0x1p-23));
  assert_true(got_accel <= accel && got_accel >= accel * (1.0 - 0x1p-23));
  for (int t = 0; t < PTYPE_COUNT; t++) /* the liquid at rest: no acceleration limit */
    s.ps.a[t][0] = s.ps.a[t][1] = t == PTYPE_FLUID ? 0.0 : 1e3;
  assert_true(sph_limit("sph acceleration") == -1.0);
}

/* A module enabled before body_force that reads body_force_current in its compute,
 * as the wall pass does: what it saw, per evaluation. */
static double seen_ax;
static PetscErrorCode reader_compute(module *self, sim *sim_) {
  double a[2];
  (void)sim_;
  body_force_current(self->data, a);
  seen_ax = a[0];
  return 0;
}

static void test_prepare_before_compute(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force_amplitude 2 -body_force_period 1"));
  OK(m->set_from_options(m, &s));
  module reader = {.name = "reader", .compute = reader_compute, .data = m};
  s.modules[0] = &reader; /* before body_force, in the order of enabling */
  for (int k = 1; k <= 3; k++) {
    s.t = 0.25 * k; /* sin(pi k/2): 2, 0, -2 */
    OK(sim_add_module_forces(&s, NULL));
    assert_close(seen_ax, 2.0 * sin(0.5 * M_PI * k), 1e-14);
  }
  s.modules[0] = sph;
}

/* A module that says it sets the rates: it adds (5, 6) to a, so that a zeroing pass before
 * it would show, and clears rates_unset when setter_sets. */
static PetscBool setter_sets, setter_saw_unset;
static int setter_calls;
static PetscErrorCode setter_compute(module *self, sim *sim_) {
  (void)self;
  setter_calls++;
  setter_saw_unset = sim_->rates_unset;
  for (PetscInt i = 0; i < sim_->ps.n_owned; i++) {
    sim_->ps.a[i][0] += 5.0;
    sim_->ps.a[i][1] += 6.0;
  }
  if (setter_sets)
    sim_->rates_unset = PETSC_FALSE;
  return 0;
}
static module setter = {.name = "setter", .needs = MODULE_SETS_RATES, .compute = setter_compute};
static PetscBool not_setter(const module *mod) {
  return mod != &setter ? PETSC_TRUE : PETSC_FALSE;
}

static void fill_a(double ax, double ay) {
  for (PetscInt i = 0; i < s.ps.n_owned + s.ps.n_ghost; i++) {
    s.ps.a[i][0] = ax;
    s.ps.a[i][1] = ay;
  }
}

static void test_first_module_sets_rates(void **state) {
  (void)state;
  OK(PetscOptionsInsertString(NULL, "-body_force 1,0 -gravity 0")); /* on the liquid only */
  OK(m->set_from_options(m, &s));
  s.modules[0] = &setter;
  setter_sets = PETSC_TRUE;
  const PetscInt ghost = s.ps.n_owned - 1; /* the last row made a ghost */
  s.ps.n_owned--;
  s.ps.n_ghost = 1;
  fill_a(1.0, 2.0);
  OK(sim_compute_module_forces(&s, NULL));
  assert_true(setter_saw_unset && !s.rates_unset);
  assert_accel(PTYPE_FLUID, 1.0 + 5.0 + 1.0, 2.0 + 6.0, 0.0); /* not zeroed, then added to */
  assert_accel(PTYPE_WALL, 6.0, 8.0, 0.0);
  assert_accel((int)ghost, 0.0, 0.0, 0.0); /* the ghost rows still start at 0 */
  /* the setter filtered out: the evaluation zeroes a, body_force adds */
  setter_calls = 0;
  fill_a(1.0, 2.0);
  OK(sim_compute_module_forces(&s, not_setter));
  assert_int_equal(setter_calls, 0);
  assert_false(s.rates_unset);
  assert_accel(PTYPE_FLUID, 1.0, 0.0, 0.0);
  assert_accel(PTYPE_WALL, 0.0, 0.0, 0.0);
  /* body_force first: zeroed, and the setter after it adds without being told to set */
  s.modules[0] = m;
  s.modules[1] = &setter;
  fill_a(1.0, 2.0);
  OK(sim_compute_module_forces(&s, NULL));
  assert_false(setter_saw_unset);
  assert_accel(PTYPE_FLUID, 1.0 + 5.0, 6.0, 0.0);
  s.modules[0] = &setter;
  s.modules[1] = m;
  /* says so, does not */
  setter_sets = PETSC_FALSE;
  assert_int_equal(sim_compute_module_forces(&s, NULL), PETSC_ERR_PLIB);
  s.rates_unset = PETSC_FALSE;
  s.modules[0] = sph;
  s.ps.n_owned++;
  s.ps.n_ghost = 0;
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_constant_with_gravity, setup, teardown),
      cmocka_unit_test_setup_teardown(test_pulsatile, setup, teardown),
      cmocka_unit_test_setup_teardown(test_types, setup, teardown),
      cmocka_unit_test_setup_teardown(test_walls_refused, setup, teardown),
      cmocka_unit_test_setup_teardown(test_option_errors, setup, teardown),
      cmocka_unit_test_setup_teardown(test_scene_defaults, setup, teardown),
      cmocka_unit_test_setup_teardown(test_sph_speed_scans, setup, teardown),
      cmocka_unit_test_setup_teardown(test_max_dt, setup, teardown),
      cmocka_unit_test_setup_teardown(test_prepare_before_compute, setup, teardown),
      cmocka_unit_test_setup_teardown(test_first_module_sets_rates, setup, teardown),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
