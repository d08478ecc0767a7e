/* Time-step limits and the kick-drift-kick integrator (src/core/integrate.c). Proves:
 *   - dt_limits_add stores name, formula and value; dt_limits_min returns the
 *     smallest value and its index (+inf and -1 with no limits); adding more than
 *     DT_LIMITS_MAX limits returns an error code;
 *   - under a constant acceleration, n velocity-Verlet steps reproduce free flight
 *     exactly: x = x0 + v0 t + a t^2/2, v = v0 + a t, with v_est = v^n + dt a;
 *   - a wall particle moves with its velocity and is never kicked;
 *   - with sub-cycled solids, the liquid's step leaves the x, v and v_est of the rows marked
 *     substepped (a solid, a liquid particle in a sub-cycled contact) to the sub-steps but
 *     for their second half kick (held: dt / 2 n_sub with the whole acceleration; respa:
 *     that with the sub-cycled share, dt/2 with the rest), and advances their density; a
 *     clot and a liquid particle beside them are kicked and drift as the liquid; the walls'
 *     densities are not integrated;
 *   - with continuity density, rho advances by dt * drho per step (two half kicks),
 *     and is left alone with summation density;
 *   - with -sph_density_predict the forces see rho^n + dt drho^n and the step
 *     ends at the trapezoid rho^n + dt/2 (drho^n + drho^{n+1});
 *   - a particle ringing against a pressure (a = -beta (rho - rho0), drho =
 *     g v_est: a particle among walls) grows at omega^2 dt/4 with the half-step
 *     density, within 10 %, and keeps its amplitude with the predicted one. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/sph.h"
#include "dmhs/integrate.h"
#include "dmhs/fields.h"

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

/* What the liquid's module declares it integrates (continuity: density rates). */
static module liquid;

/* extra: optional fields beyond SPH's (NULL-terminated, or NULL) */
static void make_sim_with(sim *s, sph_density_kind density, const char *const *extra) {
  OK(PetscMemzero(s, sizeof(*s)));
  s->comm = PETSC_COMM_SELF;
  liquid = (module){.name = "liquid",
                    .needs = density == SPH_DENSITY_CONTINUITY ? MODULE_INTEGRATES_DENSITY : 0};
  s->modules[0] = &liquid;
  s->n_modules = 1;
  s->dt = 1e-3;
  OK(unit_enable_sph_fields());
  for (const char *const *f = extra; f && *f; f++)
    OK(fields_enable(*f));
  OK(particles_create(&s->ps));
}

static void make_sim(sim *s, sph_density_kind density) {
  make_sim_with(s, density, NULL);
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

/* One liquid step with sub-cycled rows (respa: the r-RESPA split, else held): the rows marked
 * substepped (a solid, a liquid particle in a sub-cycled contact) are left to the sub-steps
 * but for their second kick, the others kicked and drifted as ever. */
static void subcycled_step(PetscBool respa) {
  static sim s;
  static const char *const sub_fields[] = {"a_hold", "substepped", NULL};
  fields_reset();
  make_sim_with(&s, SPH_DENSITY_CONTINUITY, sub_fields);
  s.substeps.on = PETSC_TRUE;
  s.substeps.respa = respa;
  s.substeps.n = 3;
  const double x0[2] = {0.1, -0.2}, v0[2] = {1.5, -0.5}, a[2] = {-3.0, 9.81}, drho = 12.0;
  const double a_hold[2] = {0.5, -2.0}; /* the forces not sub-cycled */
  /* a solid, a clot, a wall, a liquid particle, a liquid particle in contact */
  const particle_type types[] = {PTYPE_SOLID, PTYPE_CLOT, PTYPE_WALL, PTYPE_FLUID, PTYPE_FLUID};
  const int moves[] = {1, 0, 0, 0, 1};
  for (PetscInt i = 0; i < 5; i++) {
    OK(particles_add_owned(&s.ps, i, types[i], x0, v0, 1.0, 1000.0, NULL));
    for (int k = 0; k < 2; k++) {
      s.ps.a[i][k] = a[k];
      s.ps.a_hold[i][k] = a_hold[k];
      s.ps.v_est[i][k] = -9.0; /* what a sub-cycled row keeps */
    }
    s.ps.drho[i] = drho;
    s.ps.substepped[i] = moves[i];
  }
  const double dt = s.dt;
  OK(integrate_first_half(&s));
  for (int k = 0; k < 2; k++) {
    for (PetscInt i = 0; i < 5; i += 4) { /* the sub-cycled rows */
      assert_true(s.ps.x[i][k] == x0[k] && s.ps.v[i][k] == v0[k] && s.ps.v_est[i][k] == -9.0);
    }
    for (PetscInt i = 1; i < 4; i += 2) { /* the clot and the liquid */
      assert_true(s.ps.v_est[i][k] == v0[k] + dt * a[k]);
      assert_true(s.ps.v[i][k] == v0[k] + 0.5 * dt * a[k]);
      assert_true(s.ps.x[i][k] == x0[k] + dt * (v0[k] + 0.5 * dt * a[k]));
    }
    assert_true(s.ps.v_est[2][k] == v0[k] && s.ps.v[2][k] == v0[k]);
    assert_true(s.ps.x[2][k] == x0[k] + dt * v0[k]);
  }
  for (PetscInt i = 0; i < 5; i++)
    assert_true(s.ps.rho[i] == (i == 2 ? 1000.0 : 1000.0 + 0.5 * dt * drho));
  OK(integrate_second_half(&s));
  const double half = 0.5 * dt, half_sub = 0.5 * dt / 3.0;
  for (int k = 0; k < 2; k++) {
    /* held: the last sub-step's half kick with the whole acceleration; respa: the
     * sub-cycled share over it, the rest (a_hold) over the step's half */
    const double v_sub =
        respa ? v0[k] + half_sub * a[k] + (half - half_sub) * a_hold[k] : v0[k] + half_sub * a[k];
    assert_true(s.ps.v[0][k] == v_sub && s.ps.v[4][k] == v_sub);
    assert_true(s.ps.v[1][k] == v0[k] + 0.5 * dt * a[k] + 0.5 * dt * a[k]);
    assert_true(s.ps.v[3][k] == v0[k] + 0.5 * dt * a[k] + 0.5 * dt * a[k]);
    assert_true(s.ps.v[2][k] == v0[k]);
  }
  for (PetscInt i = 0; i < 5; i++)
    assert_true(s.ps.rho[i] == (i == 2 ? 1000.0 : 1000.0 + 0.5 * dt * drho + 0.5 * dt * drho));
  OK(particles_destroy(&s.ps));
  fields_reset();
}

static void test_subcycled_solid(void **state) {
  (void)state;
  subcycled_step(PETSC_FALSE);
  subcycled_step(PETSC_TRUE);
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

static void test_density_predict_trapezoid(void **state) {
  (void)state;
  static sim s;
  fields_reset();
  OK(fields_enable("drho_prev"));
  make_sim(&s, SPH_DENSITY_CONTINUITY);
  liquid.needs |= MODULE_PREDICTS_DENSITY;
  const double x0[2] = {0, 0}, v0[2] = {0, 0};
  OK(particles_add_owned(&s.ps, 1, PTYPE_FLUID, x0, v0, 1.0, 1000.0, NULL));
  s.ps.drho[0] = 12.0;
  OK(integrate_first_half(&s));
  assert_close(s.ps.rho[0], 1000.0 + s.dt * 12.0, 1e-12);
  s.ps.drho[0] = -4.0; /* the force evaluation's */
  OK(integrate_second_half(&s));
  assert_close(s.ps.rho[0], 1000.0 + 0.5 * s.dt * (12.0 - 4.0), 1e-12);
  OK(particles_destroy(&s.ps));
  fields_reset();
}

/* The largest |rho - rho0| over the first and over the last period of a
 * particle whose pressure pushes it along x, a = -beta (rho - rho0), and whose
 * density follows its predicted velocity, drho = g v_est (omega^2 = beta g). */
static void ring(PetscBool predict, double omega, double dt, int steps, double *first,
                 double *last) {
  static sim s;
  const double g = 1.0, beta = omega * omega / g, rho0 = 1000.0;
  const int period = (int)ceil(2.0 * M_PI / (omega * dt));
  const double x0[2] = {0, 0}, v0[2] = {0, 0};
  fields_reset();
  if (predict)
    OK(fields_enable("drho_prev"));
  make_sim(&s, SPH_DENSITY_CONTINUITY);
  if (predict)
    liquid.needs |= MODULE_PREDICTS_DENSITY;
  s.dt = dt;
  OK(particles_add_owned(&s.ps, 1, PTYPE_FLUID, x0, v0, 1.0, rho0 + 1e-3, NULL));
  s.ps.a[0][0] = -beta * 1e-3;
  *first = *last = 0;
  for (int n = 0; n < steps; n++) {
    OK(integrate_first_half(&s));
    s.ps.a[0][0] = -beta * (s.ps.rho[0] - rho0);
    s.ps.a[0][1] = 0;
    s.ps.drho[0] = g * s.ps.v_est[0][0];
    OK(integrate_second_half(&s));
    const double dev = fabs(s.ps.rho[0] - rho0);
    if (n < period)
      *first = PetscMax(*first, dev);
    if (n >= steps - period)
      *last = PetscMax(*last, dev);
  }
  OK(particles_destroy(&s.ps));
  fields_reset();
}

static void test_density_predict_ringing(void **state) {
  (void)state;
  const double omega = 1.0, dt = 0.05, T = 400.0;
  const int steps = (int)(T / dt);
  double first, last;
  ring(PETSC_FALSE, omega, dt, steps, &first, &last);
  const double rate = log(last / first) / T;
  print_message("half-step density: growth %.4g per unit time (omega^2 dt/4 = %.4g)\n", rate,
                0.25 * omega * omega * dt);
  assert_true(fabs(rate / (0.25 * omega * omega * dt) - 1.0) < 0.1);
  ring(PETSC_TRUE, omega, dt, steps, &first, &last);
  print_message("predicted density: amplitude x %.6f over %g periods\n", last / first,
                T * omega / (2 * M_PI));
  assert_true(last / first < 1.05 && last / first > 0.95);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_dt_limits),
      cmocka_unit_test(test_free_flight),
      cmocka_unit_test(test_subcycled_solid),
      cmocka_unit_test(test_summation_density_not_integrated),
      cmocka_unit_test(test_density_predict_trapezoid),
      cmocka_unit_test(test_density_predict_ringing),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
