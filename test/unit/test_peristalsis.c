/* Module peristalsis (src/physics/peristalsis.c, doc/cases.md) against the
 * formulas of its header comment, evaluated here by hand:
 *   - the generated schedule of n pockets (R = 2(n-1) + 5 rows): pocket k is
 *     -1 in sub-period 2k-1 and +1 in 2k+1 .. 2k+H (mod R), else 0; written out
 *     for 3 pockets with H = 2 and H = 5 (the +1 run wrapping past R);
 *   - it is a travelling wave: pocket k+1 does two sub-periods later what
 *     pocket k does, for every H;
 *   - sub-period r = floor((t - t_d)/t_w) mod R, -1 before the delay and after
 *     -peristalsis_waves waves; T_w = R t_w;
 *   - the ramp: the applied factor goes from the previous sub-period's value
 *     to the new one along 3u^2 - 2u^3, u = (fraction of t_w)/ramp;
 *   - the force on a segment particle: a_y += A F sin^2(pi (x0 - x_left - k b)/b)/m
 *     (full at the centre, half a quarter in, zero at the folds, by the initial
 *     position x0, not the current one), only on solids of segment PERISTALSIS_SEGMENT0 + k;
 *     the support -k_s (x - x0)/m - gamma v_est on every solid;
 *   - a schedule file is read as written ('#' comments, commas or blanks), and
 *     a value other than -1/0/1 or a short row is an error;
 *   - the time-step limits 0.2 sqrt(m/k_s) and 0.2/gamma; the option errors. */
#include <stdio.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/peristalsis.h"

/* 3 pockets (N = 2): R = 9 rows, pocket k columns */
static const int S_H2[9][3] = {
    {0, 0, 0},  /* r = 0 */
    {1, -1, 0}, /* r = 1: pocket 0 up (2k+1 = 1), pocket 1 down (2k-1 = 1) */
    {1, 0, 0},  /* r = 2: pocket 0 up (2k+H = 2) */
    {0, 1, -1}, /* r = 3 */
    {0, 1, 0},  {0, 0, 1},  {0, 0, 1},
    {0, 0, 0},  {-1, 0, 0}, /* r = 8: pocket 0 down (2k-1 = -1 = 8 mod 9) */
};
static const int S_H5[9][3] = {
    {0, 0, 1}, /* r = 0: pocket 2 up from r = 5 to 9 = 0 mod 9 */
    {1, -1, 0}, {1, 0, 0}, {1, 1, -1}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, {0, 1, 1}, {-1, 0, 1},
};

static void test_spec_schedule(void **state) {
  (void)state;
  for (int r = 0; r < 9; r++)
    for (int k = 0; k < 3; k++) {
      if (peristalsis_spec_value(3, 2, r, k) != S_H2[r][k])
        fail_msg("H = 2, r = %d, k = %d: %d, expected %d", r, k, peristalsis_spec_value(3, 2, r, k),
                 S_H2[r][k]);
      if (peristalsis_spec_value(3, 5, r, k) != S_H5[r][k])
        fail_msg("H = 5, r = %d, k = %d: %d, expected %d", r, k, peristalsis_spec_value(3, 5, r, k),
                 S_H5[r][k]);
    }
}

static void test_travelling_wave(void **state) {
  (void)state;
  for (PetscInt n = 2; n <= 6; n++) {
    const PetscInt R = 2 * (n - 1) + 5;
    for (PetscInt H = 1; H <= 5; H++)
      for (PetscInt k = 0; k + 1 < n; k++)
        for (PetscInt r = 0; r < R; r++)
          assert_int_equal(peristalsis_spec_value(n, H, (r + 2) % R, k + 1),
                           peristalsis_spec_value(n, H, r, k));
    /* each pocket goes down exactly once and up H times per period (H = 2) */
    for (PetscInt k = 0; k < n; k++) {
      int down = 0, up = 0;
      for (PetscInt r = 0; r < R; r++) {
        down += peristalsis_spec_value(n, 2, r, k) == -1;
        up += peristalsis_spec_value(n, 2, r, k) == 1;
      }
      assert_int_equal(down, 1);
      assert_int_equal(up, 2);
    }
  }
}

/* ---- the module ---- */

static sim s;
static module *m;
static const double b = 0.02, x_left = 0.1, F = 0.5;

static int setup(void **state) {
  (void)state;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  fields_reset();
  OK(fields_enable("segment")); /* as the module's options pass does */
  OK(fields_enable("x0"));
  OK(particles_create(&s.ps));
  OK(peristalsis_module_create(&m));
  OK(peristalsis_set_geometry(m, 3, b, x_left));
  return 0;
}

static int teardown(void **state) {
  (void)state;
  OK(m->destroy(m));
  OK(PetscFree(m));
  OK(particles_destroy(&s.ps));
  OK(PetscOptionsClear(NULL));
  options_forget();
  return 0;
}

static void configure(const char *options) {
  OK(PetscOptionsInsertString(NULL, options));
  OK(m->set_from_options(m, &s));
  OK(m->setup(m, &s));
}

static void test_subperiods(void **state) {
  (void)state;
  configure("-peristalsis_tw 0.1 -peristalsis_delay 0.05 -peristalsis_waves 2 -peristalsis_ramp 0");
  double t_w, T_w, delay;
  PetscInt H, rows;
  OK(peristalsis_get(m, &t_w, &T_w, &H, &rows, &delay));
  assert_true(t_w == 0.1 && H == 2 && rows == 9 && delay == 0.05);
  assert_close(T_w, 0.9, 1e-15);
  assert_int_equal(peristalsis_subperiod(m, 0.0), -1);
  assert_int_equal(peristalsis_subperiod(m, 0.049), -1);
  assert_int_equal(peristalsis_subperiod(m, 0.05), 0);
  assert_int_equal(peristalsis_subperiod(m, 0.05 + 0.35), 3);
  assert_int_equal(peristalsis_subperiod(m, 0.05 + 0.9 + 0.15), 1);  /* second wave */
  assert_int_equal(peristalsis_subperiod(m, 0.05 + 1.8 + 0.01), -1); /* after 2 waves */
  /* the value follows the schedule, sub-period by sub-period */
  for (int r = 0; r < 9; r++)
    for (int k = 0; k < 3; k++) {
      const double t = 0.05 + 0.1 * r + 0.05;
      assert_int_equal(peristalsis_value(m, t, k), S_H2[r][k]);
      assert_close(peristalsis_amplitude(m, t, k), S_H2[r][k], 0); /* no ramp */
    }
  assert_int_equal(peristalsis_value(m, 0.2, 3), 0); /* no pocket 3 */
  assert_int_equal(peristalsis_value(m, 0.01, 0), 0);
}

static void test_ramp(void **state) {
  (void)state;
  configure("-peristalsis_tw 0.1 -peristalsis_ramp 0.5");
  /* pocket 0 goes 0 -> +1 at r = 1 (t = 0.1), pocket 1 0 -> -1 */
  const struct {
    double fraction, w; /* of the sub-period; smoothstep 3u^2 - 2u^3 of u = fraction/0.5 */
  } at[] = {{0.1, 0.104}, {0.25, 0.5}, {0.4, 0.896}, {0.6, 1.0}, {0.9, 1.0}};
  for (size_t j = 0; j < sizeof(at) / sizeof(at[0]); j++) {
    const double t = 0.1 + 0.1 * at[j].fraction;
    assert_close(peristalsis_amplitude(m, t, 0), at[j].w, 1e-6);
    assert_close(peristalsis_amplitude(m, t, 1), -at[j].w, 1e-6);
    assert_close(peristalsis_amplitude(m, t, 2), 0.0, 0);
  }
  /* a quarter into r = 3 (u = 0.5, w = 0.5): pocket 0 from +1 (r = 2) to 0, pocket 1
   * from 0 to +1, pocket 2 from 0 to -1 */
  assert_close(peristalsis_amplitude(m, 0.325, 0), 0.5, 1e-6);
  assert_close(peristalsis_amplitude(m, 0.325, 1), 0.5, 1e-6);
  assert_close(peristalsis_amplitude(m, 0.325, 2), -0.5, 1e-6);
}

/* a_y of each particle after one compute at t, from a = 0 */
static void compute_at(double t) {
  for (PetscInt i = 0; i < s.ps.n_owned; i++)
    s.ps.a[i][0] = s.ps.a[i][1] = 0.0;
  s.t = t;
  OK(m->compute(m, &s));
}

static PetscInt add(particle_type type, PetscInt segment, double x0, double y0, double mass) {
  const double x[2] = {x0, y0}, v[2] = {0, 0};
  PetscInt i;
  OK(particles_add_owned(&s.ps, s.ps.n_owned, type, x, v, mass, 1000.0, &i));
  s.ps.segment[i] = segment;
  return i;
}

static void test_force_profile(void **state) {
  (void)state;
  const double mass = 2e-3;
  /* pocket 1 spans [x_left + b, x_left + 2b] */
  const PetscInt centre = add(PTYPE_SOLID, PERISTALSIS_SEGMENT0 + 1, x_left + 1.5 * b, 0.0, mass);
  const PetscInt quarter = add(PTYPE_SOLID, PERISTALSIS_SEGMENT0 + 1, x_left + 1.25 * b, 0.0, mass);
  const PetscInt fold = add(PTYPE_SOLID, PERISTALSIS_SEGMENT0 + 1, x_left + 2.0 * b, 0.0, mass);
  const PetscInt p0 = add(PTYPE_SOLID, PERISTALSIS_SEGMENT0 + 0, x_left + 0.5 * b, 0.0, mass);
  const PetscInt fluid = add(PTYPE_FLUID, PERISTALSIS_SEGMENT0 + 1, x_left + 1.5 * b, 0.0, mass);
  const PetscInt untagged = add(PTYPE_SOLID, 0, x_left + 1.5 * b, 0.0, mass);
  const PetscInt beyond = add(PTYPE_SOLID, PERISTALSIS_SEGMENT0 + 3, x_left + 3.5 * b, 0.0, mass);
  configure("-peristalsis_tw 0.1 -peristalsis_ramp 0 -peristalsis_force 0.5 "
            "-peristalsis_support 0 -peristalsis_damping 0");
  /* r = 3: pocket 1 +1, pocket 0 0 */
  compute_at(0.35);
  assert_close(s.ps.a[centre][1], F / mass, 1e-12 * F / mass);
  assert_close(s.ps.a[quarter][1], 0.5 * F / mass, 1e-12 * F / mass); /* sin^2(pi/4) */
  assert_close(s.ps.a[fold][1], 0.0, 1e-12 * F / mass);
  assert_close(s.ps.a[centre][0], 0.0, 0);
  assert_close(s.ps.a[p0][1], 0.0, 0);
  assert_close(s.ps.a[fluid][1], 0.0, 0);
  assert_close(s.ps.a[untagged][1], 0.0, 0);
  assert_close(s.ps.a[beyond][1], 0.0, 0);
  /* r = 1: pocket 1 -1, pocket 0 +1 */
  compute_at(0.15);
  assert_close(s.ps.a[centre][1], -F / mass, 1e-12 * F / mass);
  assert_close(s.ps.a[p0][1], F / mass, 1e-12 * F / mass);
  /* the profile is by the initial position: moving the particle changes nothing */
  s.ps.x[centre][0] += 0.4 * b;
  compute_at(0.15);
  assert_close(s.ps.a[centre][1], -F / mass, 1e-12 * F / mass);
  /* before the wave (delay 0: r = 0, every pocket 0) */
  compute_at(0.05);
  assert_close(s.ps.a[centre][1], 0.0, 0);
}

static void test_support_and_damping(void **state) {
  (void)state;
  const double mass = 2e-3, ks = 40.0, gamma = 300.0;
  const PetscInt i = add(PTYPE_SOLID, 0, 0.3, 0.01, mass);
  const PetscInt f = add(PTYPE_FLUID, 0, 0.3, 0.01, mass);
  configure("-peristalsis_support 40 -peristalsis_damping 300");
  s.ps.x[i][0] += 1e-3;
  s.ps.x[i][1] -= 2e-3;
  s.ps.v_est[i][0] = 0.01;
  s.ps.v_est[i][1] = -0.02;
  s.ps.x[f][0] += 1e-3;
  s.ps.v_est[f][0] = 0.01;
  compute_at(0.0);
  assert_close(s.ps.a[i][0], -ks * 1e-3 / mass - gamma * 0.01, 1e-9);
  assert_close(s.ps.a[i][1], ks * 2e-3 / mass + gamma * 0.02, 1e-9);
  assert_close(s.ps.a[f][0], 0.0, 0);
  assert_close(s.ps.a[f][1], 0.0, 0);
  dt_limits l = {0};
  int which;
  OK(m->max_dt(m, &s, &l));
  assert_int_equal(l.n, 2);
  const double want_k = 0.2 * sqrt(mass / ks), want_g = 0.2 / gamma;
  assert_true(l.item[0].value <= want_k && l.item[0].value >= want_k * (1 - 0x1p-23));
  assert_true(l.item[1].value <= want_g && l.item[1].value >= want_g * (1 - 0x1p-23));
  assert_true(dt_limits_min(&l, &which) == l.item[1].value);
  assert_int_equal(which, 1);
}

static void write_file(const char *path, const char *text) {
  FILE *fp = fopen(path, "w");
  assert_non_null(fp);
  fputs(text, fp);
  fclose(fp);
}

static void test_schedule_file(void **state) {
  (void)state;
  const char *path = "unit_peristalsis_schedule.txt"; /* in the test's working directory */
  char opts[128];
  write_file(path, "# pocket 0 1 2\n1 0 -1\n\n0,1,0  # second row\n -1 , 0 , 1\n");
  snprintf(opts, sizeof(opts), "-peristalsis_tw 0.1 -peristalsis_ramp 0 -peristalsis_schedule %s",
           path);
  configure(opts);
  PetscInt rows;
  OK(peristalsis_get(m, NULL, NULL, NULL, &rows, NULL));
  assert_int_equal(rows, 3);
  const int want[3][3] = {{1, 0, -1}, {0, 1, 0}, {-1, 0, 1}};
  for (int r = 0; r < 3; r++)
    for (int k = 0; k < 3; k++)
      assert_int_equal(peristalsis_value(m, 0.1 * r + 0.05, k), want[r][k]);
  assert_int_equal(peristalsis_value(m, 0.35, 0), 1); /* repeats: row 0 again */
  /* a value 2, then a short row: errors */
  write_file(path, "1 0 -1\n0 2 0\n");
  assert_int_equal(m->setup(m, &s), PETSC_ERR_FILE_UNEXPECTED);
  write_file(path, "1 0 -1\n0 1\n");
  assert_int_equal(m->setup(m, &s), PETSC_ERR_FILE_UNEXPECTED);
  write_file(path, "# nothing\n");
  assert_int_equal(m->setup(m, &s), PETSC_ERR_FILE_UNEXPECTED);
  remove(path);
  assert_int_equal(m->setup(m, &s), PETSC_ERR_FILE_OPEN);
}

static void test_option_errors(void **state) {
  (void)state;
  const char *bad[] = {"-peristalsis_tw 0", "-peristalsis_h 0", "-peristalsis_ramp 1.5",
                       "-peristalsis_delay -1", "-peristalsis_support -1"};
  for (size_t k = 0; k < sizeof(bad) / sizeof(bad[0]); k++) {
    module *fresh; /* a failed pass leaves the bad value in the module: one module per case */
    OK(PetscOptionsClear(NULL));
    OK(PetscOptionsInsertString(NULL, bad[k]));
    OK(peristalsis_module_create(&fresh));
    if (fresh->set_from_options(fresh, &s) != PETSC_ERR_ARG_OUTOFRANGE)
      fail_msg("%s was accepted", bad[k]);
    OK(fresh->destroy(fresh));
    OK(PetscFree(fresh));
  }
  /* the scene must give the geometry first */
  module *bare;
  OK(PetscOptionsClear(NULL));
  OK(peristalsis_module_create(&bare));
  OK(bare->set_from_options(bare, &s));
  assert_int_equal(bare->setup(bare, &s), PETSC_ERR_ORDER);
  OK(bare->destroy(bare));
  OK(PetscFree(bare));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_spec_schedule),
      cmocka_unit_test(test_travelling_wave),
      cmocka_unit_test_setup_teardown(test_subperiods, setup, teardown),
      cmocka_unit_test_setup_teardown(test_ramp, setup, teardown),
      cmocka_unit_test_setup_teardown(test_force_profile, setup, teardown),
      cmocka_unit_test_setup_teardown(test_support_and_damping, setup, teardown),
      cmocka_unit_test_setup_teardown(test_schedule_file, setup, teardown),
      cmocka_unit_test_setup_teardown(test_option_errors, setup, teardown),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
