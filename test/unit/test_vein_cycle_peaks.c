/* The measurement point's peak stress per cycle (src/scenes/vein/vein_cycle_peaks.c): a history of
 * rows every 0.02 s from the probe time T/4 of a 4 s period, with output times a step off
 * their nominal values as a run writes them, counts every whole cycle once: 4 for a run that
 * ends at 15.999999 s for 16 s with the point chosen at 1.0000013 s; each cycle's peak is
 * its own row's; a point chosen after a cycle's probe time leaves that cycle out; a run
 * stopped mid-cycle counts only the whole ones; no history gives none. */
#include "unit_common.h"
#include "scenes/vein/vein_cycle_peaks.h"

#define T      4.0
#define DT_ROW 0.02

/* rows from t0 to t1, each time off by +-1.3e-6 s (alternating), stress 1 except a peak
 * of 10 + c in the middle of cycle c */
static PetscInt make_history(double (*h)[3], double t0, double t1) {
  PetscInt n = 0;
  for (PetscInt k = (PetscInt)llround(t0 / DT_ROW); k * DT_ROW <= t1 + 1e-9; k++) {
    const double t = k * DT_ROW + (k % 2 ? -1.3e-6 : 1.3e-6);
    const PetscInt c = (PetscInt)floor(k * DT_ROW / T - 1e-9);
    const int mid = fabs(k * DT_ROW - (c + 0.5) * T) < 1e-9;
    h[n][0] = t;
    h[n][1] = mid ? 10.0 + (double)c : 1.0;
    h[n][2] = 0;
    n++;
  }
  return n;
}

static void test_whole_run(void **state) {
  static double h[1000][3];
  double peaks[8];
  (void)state;
  const PetscInt n = make_history(h, 1.0, 16.0);
  h[0][0] = 1.0000013; /* chosen just after the probe time */
  assert_true(vein_cycle_peaks_max(T, 15.999999) <= 8);
  assert_int_equal(vein_cycle_peaks((const double(*)[3])h, n, T, 15.999999, peaks), 4);
  for (int c = 0; c < 4; c++)
    assert_close(peaks[c], 10.0 + c, 0);
  assert_int_equal(vein_cycle_peaks((const double(*)[3])h, n, T, 16.000001, peaks), 4);
}

static void test_late_choice_and_partial_run(void **state) {
  static double h[1000][3];
  double peaks[8];
  (void)state;
  /* chosen at 2 s, after cycle 1's probe time: cycles 2-4 */
  PetscInt n = make_history(h, 2.0, 16.0);
  assert_int_equal(vein_cycle_peaks((const double(*)[3])h, n, T, 16.0, peaks), 3);
  assert_close(peaks[0], 11.0, 0);
  /* stopped at 9 s: cycles 1 and 2 */
  n = make_history(h, 1.0, 9.0);
  assert_int_equal(vein_cycle_peaks((const double(*)[3])h, n, T, 9.0, peaks), 2);
  assert_close(peaks[1], 11.0, 0);
  assert_int_equal(vein_cycle_peaks((const double(*)[3])h, 0, T, 9.0, peaks), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_whole_run),
      cmocka_unit_test(test_late_choice_and_partial_run),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
