/* Time-step limits and the kick-drift-kick integrator (src/core/integrate.c). Proves:
 *   - dt_limits_add stores name, formula and value; dt_limits_min returns the
 *     smallest value and its index (+inf and -1 with no limits); adding more than
 *     DT_LIMITS_MAX limits returns an error code;
 *   - under a constant acceleration, n velocity-Verlet steps reproduce free flight
 *     exactly: x = x0 + v0 t + a t^2/2, v = v0 + a t, with v_est = v^n + dt a;
 *   - a wall particle moves with its velocity and is never kicked;
 *   - with continuity density, rho advances by dt * drho per step (two half kicks),
 *     and is left alone with summation density. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/integrate.h"

static void test_dt_limits(void **state) {
  (void)state;
  dt_limits l = {0};
  int which = 7;
  assert_true(isinf(dt_limits_min(&l, &which)) && which == -1);
  OK(dt_limits_add(&l, "sph sound speed", "0.25 h / c0", 3e-5));
  OK(dt_limits_add(&l, "sph viscous", "0.125 h^2 / nu", 1e-5));
  OK(dt_limits_add(&l, "body force", "0.25 sqrt(h / |F|)", 2e-5));
  assert_int_equal(l.n, 3);
  assert_string_equal(l.item[1].name, "sph viscous");
  assert_string_equal(l.item[2].formula, "0.25 sqrt(h / |F|)");
  /* limits are rounded down to 24 significant bits (rank invariance of
   * geometric limits): never above the value, within 2^-23 of it */
  const double got = dt_limits_min(&l, &which);
  assert_true(got <= 1e-5 && got >= 1e-5 * (1.0 - 0x1p-23));
  assert_true(l.item[0].value <= 3e-5 && l.item[0].value >= 3e-5 * (1.0 - 0x1p-23));
  assert_int_equal(which, 1);
  OK(dt_limits_add(&l, "later and smaller", "x", 5e-6));
  assert_true(dt_limits_min(&l, &which) <= 5e-6 && dt_limits_min(&l, &which) > 4.99999e-6);
  assert_int_equal(which, 3);
  while (l.n < DT_LIMITS_MAX)
    OK(dt_limits_add(&l, "filler", "x", 1.0));
  assert_int_equal(dt_limits_add(&l, "one too many", "x", 1.0), PETSC_ERR_PLIB);
  assert_int_equal(l.n, DT_LIMITS_MAX);
}

static void make_sim(sim *s, sph_density_kind density) {
  OK(PetscMemzero(s, sizeof(*s)));
  s->comm = PETSC_COMM_SELF;
  s->sph_enabled = PETSC_TRUE;
  s->sph.density = density;
  s->dt = 1e-3;
  OK(particles_create(&s->ps));
}

static void test_free_flight(void **state) {
  (void)state;
  static sim s;
  make_sim(&s, SPH_DENSITY_CONTINUITY);
  const double x0[2] = {0.1, -0.2}, v0[2] = {1.5, -0.5}, a[2] = {-3.0, 9.81}, drho = 12.0;
  OK(particles_add_owned(&s.ps, 1, PTYPE_FLUID, x0, v0, 1.0, 1000.0, NULL));
  OK(particles_add_owned(&s.ps, 2, PTYPE_WALL, x0, v0, 1.0, 1000.0, NULL));
  const int steps = 250;
  for (int n = 0; n < steps; n++) {
    /* the "force evaluation": the same acceleration and density rate for both */
    for (int i = 0; i < 2; i++) {
      s.ps.a[i][0] = a[0];
      s.ps.a[i][1] = a[1];
      s.ps.drho[i] = drho;
    }
    const double vn[2] = {s.ps.v[0][0], s.ps.v[0][1]};
    OK(integrate_first_half(&s));
    assert_close(s.ps.v_est[0][0], vn[0] + s.dt * a[0], 1e-13);
    assert_close(s.ps.v_est[0][1], vn[1] + s.dt * a[1], 1e-13);
    OK(integrate_second_half(&s));
  }
  const double t = steps * s.dt;
  for (int k = 0; k < 2; k++) {
    assert_close(s.ps.x[0][k], x0[k] + v0[k] * t + 0.5 * a[k] * t * t, 1e-12);
    assert_close(s.ps.v[0][k], v0[k] + a[k] * t, 1e-12);
    /* the wall: uniform motion, velocity unchanged */
    assert_close(s.ps.x[1][k], x0[k] + v0[k] * t, 1e-12);
    assert_true(s.ps.v[1][k] == v0[k]);
  }
  assert_close(s.ps.rho[0], 1000.0 + drho * t, 1e-9);
  assert_true(s.ps.rho[1] == 1000.0);
  OK(particles_destroy(&s.ps));
}

static void test_summation_density_not_integrated(void **state) {
  (void)state;
  static sim s;
  make_sim(&s, SPH_DENSITY_SUMMATION);
  const double x0[2] = {0, 0}, v0[2] = {0, 0};
  OK(particles_add_owned(&s.ps, 1, PTYPE_FLUID, x0, v0, 1.0, 1000.0, NULL));
  s.ps.drho[0] = 50.0;
  OK(integrate_first_half(&s));
  OK(integrate_second_half(&s));
  assert_true(s.ps.rho[0] == 1000.0);
  OK(particles_destroy(&s.ps));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_dt_limits),
      cmocka_unit_test(test_free_flight),
      cmocka_unit_test(test_summation_density_not_integrated),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
