/* No non-finite value reaches an output file. Proves:
 *   - integrate_check_state stops at a non-finite acceleration or density rate
 *     (a finite state otherwise), not only position, velocity, density, pressure;
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
      cmocka_unit_test(test_guard_fields),
      cmocka_unit_test(test_csv_rows),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
