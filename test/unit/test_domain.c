/* The simulation box (src/core/domain.c). Proves, with x periodic on [0.5, 2.5)
 * and y closed on [0, 1]:
 *   - minimum image: separations, including ones several periods long and exactly
 *     half a period, become the nearest image along x; y is never changed;
 *   - wrap: positions on the boundary, just inside/outside it, and several periods
 *     away land in [lo, hi) along x, shifted by a whole number of periods; y is
 *     never changed; also for thousands of random boxes and points one ulp
 *     below hi (the round-off case);
 *   - domain_contains tests only closed directions, boundary included;
 *   - domain_check_ghost_width rejects a periodic length <= 2 * width and an
 *     empty box (error code returned), and accepts a closed direction of any length. */
#include "unit_common.h"
#include "dmhs/domain.h"

static const domain box = {
    .lo = {0.5, 0.0}, .hi = {2.5, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};

static void test_min_image(void **state) {
  (void)state;
  const double cases[][3] = {/* dx in, dx out, dy (kept) */
                             {0.3, 0.3, 1.7},   {-0.3, -0.3, -1.7}, {1.5, -0.5, 0.0},
                             {-1.5, 0.5, 0.2},  {4.3, 0.3, 5.0},    {-5.7, 0.3, -3.3},
                             {2.0, 0.0, 0.9},   {-6.0, 0.0, 0.1},   {0.999, 0.999, 0.0},
                             {1.001, -0.999, 0}};
  for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
    double d[2] = {cases[c][0], cases[c][2]};
    domain_min_image(&box, d);
    assert_close(d[0], cases[c][1], 1e-14);
    assert_true(d[1] == cases[c][2]);
  }
  /* exactly half a period: either image, both at distance L/2 */
  for (int s = -1; s <= 1; s += 2) {
    double d[2] = {s * 1.0, 0.0};
    domain_min_image(&box, d);
    assert_close(fabs(d[0]), 1.0, 1e-15);
    double e[2] = {s * 3.0, 0.0};
    domain_min_image(&box, e);
    assert_close(fabs(e[0]), 1.0, 1e-15);
  }
}

static void test_wrap(void **state) {
  (void)state;
  const double cases[][2] = {
      {0.5, 0.5},   {2.5, 0.5},    {1.7, 1.7},  {0.25, 2.25}, {2.75, 0.75},
      {6.75, 0.75}, {-5.25, 0.75}, {10.5, 0.5}, {-3.5, 0.5},  {0.5 + 3 * 2.0 + 0.25, 0.75},
  };
  for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
    double x[2] = {cases[c][0], 7.5}; /* y outside the closed box: left alone */
    domain_wrap(&box, x);
    assert_close(x[0], cases[c][1], 1e-14);
    assert_true(x[0] >= box.lo[0] && x[0] < box.hi[0]);
    assert_true(x[1] == 7.5);
  }
}

/* Random boxes and awkward points: the result is in [lo, hi) and a whole number
 * of periods from the input. */
static void test_wrap_round_off(void **state) {
  (void)state;
  unit_rng g = {99};
  for (int trial = 0; trial < 20000; trial++) {
    domain d = {.lo = {unit_range(&g, -3, 3), 0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
    d.hi[0] = d.lo[0] + unit_range(&g, 0.01, 5.0);
    d.hi[1] = 1.0;
    const double L = domain_length(&d, 0);
    const double pts[] = {nextafter(d.hi[0], -INFINITY),      d.hi[0], nextafter(d.hi[0], INFINITY),
                          nextafter(d.lo[0], -INFINITY),      d.lo[0], nextafter(d.lo[0], INFINITY),
                          d.lo[0] + unit_range(&g, -4, 5) * L};
    for (size_t k = 0; k < sizeof(pts) / sizeof(pts[0]); k++) {
      double x[2] = {pts[k], 0.5};
      domain_wrap(&d, x);
      if (!(x[0] >= d.lo[0] && x[0] < d.hi[0]))
        fail_msg("wrap of %.17g into [%.17g, %.17g) gave %.17g", pts[k], d.lo[0], d.hi[0], x[0]);
      const double periods = (pts[k] - x[0]) / L;
      assert_close(periods, round(periods), 1e-9);
    }
  }
}

static void test_contains(void **state) {
  (void)state;
  const double inside[][2] = {{100.0, 0.0}, {-7.0, 1.0}, {1.0, 0.5}};
  const double outside[][2] = {{1.0, -1e-12}, {1.0, 1.0 + 1e-12}, {-50.0, 3.0}};
  for (int k = 0; k < 3; k++) {
    assert_true(domain_contains(&box, inside[k]));
    assert_false(domain_contains(&box, outside[k]));
  }
}

static void test_ghost_width_check(void **state) {
  (void)state;
  /* period 2 along x: width must be < 1 */
  assert_int_equal(domain_check_ghost_width(&box, 0.999), 0);
  assert_int_equal(domain_check_ghost_width(&box, 1.0), PETSC_ERR_ARG_OUTOFRANGE);
  assert_int_equal(domain_check_ghost_width(&box, 1.5), PETSC_ERR_ARG_OUTOFRANGE);
  /* the closed y direction (length 1) does not limit the width */
  domain closed = box;
  closed.periodic[0] = PETSC_FALSE;
  assert_int_equal(domain_check_ghost_width(&closed, 5.0), 0);
  /* y periodic too: its length 1 now needs width < 0.5 */
  domain both = box;
  both.periodic[1] = PETSC_TRUE;
  assert_int_equal(domain_check_ghost_width(&both, 0.49), 0);
  assert_int_equal(domain_check_ghost_width(&both, 0.5), PETSC_ERR_ARG_OUTOFRANGE);
  /* empty box */
  domain empty = box;
  empty.hi[1] = empty.lo[1];
  assert_int_equal(domain_check_ghost_width(&empty, 0.1), PETSC_ERR_ARG_OUTOFRANGE);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_min_image),         cmocka_unit_test(test_wrap),
      cmocka_unit_test(test_wrap_round_off),    cmocka_unit_test(test_contains),
      cmocka_unit_test(test_ghost_width_check),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
