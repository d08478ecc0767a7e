/* No non-finite value reaches an output file. Proves:
 *   - integrate_check_state stops at a non-finite acceleration or density rate
 *     (a finite state otherwise), not only position, velocity, density, pressure;
 *   - integrate_second_half_checked (the step loop's second kick and check in two passes)
 *     leaves the same bits as integrate_second_half, and stops where integrate_check_state
 *     stops: a non-finite value of every checked field, a density <= 0, a particle outside
 *     a closed side of the box;
 *   - io_guard_finite refuses to write a snapshot's or checkpoint's fields when
 *     one value is NaN or inf, and only the fields the file holds are checked;
 *   - csv_line / csv_row refuse a row with nan or inf in any column and write
 *     nothing of it; headers, empty cells and finite rows go through. */
#include <unistd.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/integrate.h"
#include "dmhs/csv.h"
#include "io/guard.h"

static void make_sim(sim *s) {
  OK(PetscMemzero(s, sizeof(*s)));
  s->comm = PETSC_COMM_SELF;
  s->dom.lo[0] = s->dom.lo[1] = -1;
  s->dom.hi[0] = s->dom.hi[1] = 1;
  OK(unit_enable_sph_fields());
  OK(particles_create(&s->ps));
  const double x[2] = {0.1, 0.2}, v[2] = {0, 0};
  for (int k = 0; k < 3; k++)
    OK(particles_add_owned(&s->ps, 10 + k, PTYPE_FLUID, x, v, 1.0, 1000.0, NULL));
}

static void test_check_state(void **state) {
  (void)state;
  static sim s;
  make_sim(&s);
  OK(integrate_check_state(&s));
  s.ps.a[1][1] = INFINITY;
  assert_int_equal(integrate_check_state(&s), PETSC_ERR_FP);
  s.ps.a[1][1] = 0;
  s.ps.drho[2] = NAN;
  assert_int_equal(integrate_check_state(&s), PETSC_ERR_FP);
  s.ps.drho[2] = 0;
  OK(integrate_check_state(&s));
  OK(particles_destroy(&s.ps));
}

static void test_second_half_checked(void **state) {
  (void)state;
  static sim s, ref;
  make_sim(&s);
  make_sim(&ref);
  const particle_type types[] = {PTYPE_WALL, PTYPE_SOLID, PTYPE_CLOT};
  for (PetscInt i = 0; i < 3; i++)
    for (sim *t = &s; t; t = t == &s ? &ref : NULL) {
      t->dt = 1e-3;
      t->ps.type[i] = types[i];
      t->ps.v[i][0] = 0.3 * (double)(i + 1);
      t->ps.a[i][0] = -2.0 * (double)(i + 1);
      t->ps.a[i][1] = 7.0;
      t->ps.drho[i] = 11.0;
    }
  OK(integrate_second_half_checked(&s));
  OK(integrate_second_half(&ref));
  for (PetscInt i = 0; i < 3; i++)
    assert_true(s.ps.v[i][0] == ref.ps.v[i][0] && s.ps.v[i][1] == ref.ps.v[i][1] &&
                s.ps.rho[i] == ref.ps.rho[i]);
  /* each field the check reads, made bad in turn on the clot (row 2) */
  double *bad_at[] = {&s.ps.x[2][1], &s.ps.v[2][0], &s.ps.a[2][1],
                      &s.ps.rho[2],  &s.ps.p[2],    &s.ps.drho[2]};
  for (size_t k = 0; k < sizeof(bad_at) / sizeof(bad_at[0]); k++) {
    /* a NaN in a or drho reaches v or rho through the kick: the row is restored whole */
    const double keep = *bad_at[k], v0 = s.ps.v[2][0], v1 = s.ps.v[2][1], rho = s.ps.rho[2];
    *bad_at[k] = NAN;
    assert_int_equal(integrate_second_half_checked(&s), PETSC_ERR_FP);
    *bad_at[k] = keep;
    s.ps.v[2][0] = v0;
    s.ps.v[2][1] = v1;
    s.ps.rho[2] = rho;
  }
  s.ps.rho[2] = -1.0; /* after the kick: still <= 0 */
  assert_int_equal(integrate_second_half_checked(&s), PETSC_ERR_FP);
  s.ps.rho[2] = 1000.0;
  s.ps.x[0][0] = 1.5; /* outside the closed box */
  assert_int_equal(integrate_second_half_checked(&s), PETSC_ERR_FP);
  s.ps.x[0][0] = 0.1;
  OK(integrate_second_half_checked(&s));
  OK(particles_destroy(&s.ps));
  OK(particles_destroy(&ref.ps));
}

static void test_guard_fields(void **state) {
  (void)state;
  static sim s;
  make_sim(&s);
  OK(io_guard_finite(&s, FIELD_OUTPUT, "snap.h5"));
  s.ps.a[2][0] = -INFINITY; /* a is in snapshots and checkpoints */
  assert_int_equal(io_guard_finite(&s, FIELD_OUTPUT, "snap.h5"), PETSC_ERR_FP);
  assert_int_equal(io_guard_finite(&s, FIELD_CHECKPOINT, "checkpoint.h5"), PETSC_ERR_FP);
  s.ps.a[2][0] = 0;
  s.ps.v_est[0][1] = NAN; /* in neither */
  OK(io_guard_finite(&s, FIELD_OUTPUT | FIELD_CHECKPOINT, "either.h5"));
  s.ps.x_build[0][1] = NAN; /* checkpoints only */
  OK(io_guard_finite(&s, FIELD_OUTPUT, "snap.h5"));
  assert_int_equal(io_guard_finite(&s, FIELD_CHECKPOINT, "checkpoint.h5"), PETSC_ERR_FP);
  OK(particles_destroy(&s.ps));
}

static void test_csv_rows(void **state) {
  (void)state;
  char path[] = "/tmp/dmhs-test-guard-XXXXXX", text[256] = {0};
  const int fd = mkstemp(path);
  assert_true(fd >= 0);
  close(fd);
  FILE *f = fopen(path, "w");
  assert_non_null(f);
  OK(csv_line(f, "x.csv", "# a comment, with inf words: nan\nt,inflow,near\n"));
  OK(csv_row(f, "x.csv", "%g,%g,%s\n", 0.5, 1.0, ""));
  assert_int_equal(csv_row(f, "x.csv", "%g,%g,%g\n", 1.0, NAN, 2.0), PETSC_ERR_FP);
  assert_int_equal(csv_row(f, "x.csv", "%g,%g,%g\n", 1.0, 2.0, -INFINITY), PETSC_ERR_FP);
  assert_int_equal(csv_line(f, "x.csv", "inf,1,2\n"), PETSC_ERR_FP);
  fclose(f);
  f = fopen(path, "r");
  assert_int_equal(fread(text, 1, sizeof(text) - 1, f) > 0, 1);
  fclose(f);
  unlink(path);
  assert_string_equal(text, "# a comment, with inf words: nan\nt,inflow,near\n0.5,1,\n");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_check_state),
      cmocka_unit_test(test_second_half_checked),
      cmocka_unit_test(test_guard_fields),
      cmocka_unit_test(test_csv_rows),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
