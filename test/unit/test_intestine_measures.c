/* The colon's measures (src/scenes/intestine/intestine_measures.c, doc/theory.md,
 * "Peristalsis and tracking") on synthetic rows whose answers are known:
 *   - a line fitted to x = x0 + u t over a window is exact (slope, x0, R^2 = 1),
 *     takes only the window's rows, and is undefined with fewer than 2;
 *   - whole waves count from t_d, a row up to tol early counts, the schedule's
 *     waves cap them;
 *   - u_F is the line over the whole waves (not the first wave): a front that
 *     stays put over the first wave, then climbs, gets the whole run's slope,
 *     computed here by the closed-form least squares, with its R^2, even
 *     where the still wave bends it below r2_min (the initial slope, which
 *     holds that wave, fits worse); a steady climb with pulses fits the line
 *     at R^2 >= 0.99 and gives u within 2 %; rows past the last whole wave and
 *     after the schedule's last wave are left out;
 *   - a front that climbs for 3 waves and then stalls (the thesis's Fig. 3.5 c)
 *     gets the initial slope, exactly the climb's, and says so;
 *   - less than one whole wave: u_F undefined (NAN) with the reason;
 *   - alpha at an instant is the first row at or after it;
 *   - u_P = alpha/(1 - alpha) V_w/(N+1), u_S = alpha V_w; undefined alpha gives
 *     both undefined, alpha = 1 leaves u_P undefined;
 *   - Re = b u/nu only for u > 0. */
#include <string.h>
#include "unit_common.h"
#include "scenes/intestine/intestine_measures.h"

#define NROWS 4000

/* closed-form least-squares slope and R^2 of the rows with t in [t0, t1] */
static void ls_reference(const double *t, const double *x, int n, double t0, double t1,
                         double *slope, double *r2) {
  double st = 0, sx = 0, m = 0;
  for (int i = 0; i < n; i++)
    if (t[i] >= t0 - 1e-12 && t[i] <= t1 + 1e-12) {
      st += t[i];
      sx += x[i];
      m++;
    }
  const double tm = st / m, xm = sx / m;
  double stt = 0, stx = 0, sxx = 0;
  for (int i = 0; i < n; i++)
    if (t[i] >= t0 - 1e-12 && t[i] <= t1 + 1e-12) {
      stt += (t[i] - tm) * (t[i] - tm);
      stx += (t[i] - tm) * (x[i] - xm);
      sxx += (x[i] - xm) * (x[i] - xm);
    }
  *slope = stx / stt;
  *r2 = stx * stx / (stt * sxx);
}

static void test_line(void **state) {
  (void)state;
  double t[50], x[50];
  for (int i = 0; i < 50; i++) {
    t[i] = 0.1 * i;
    x[i] = 0.01 + 0.002 * t[i];
  }
  x[0] = 5; /* outside the window below: must not count */
  intestine_line L;
  OK(intestine_measures_line(t, x, 50, 1.0, 3.0, 1e-9, &L));
  assert_int_equal(L.n, 21);
  assert_close(L.slope, 0.002, 1e-12);
  assert_close(L.x0, 0.01 + 0.002 * 1.0, 1e-12);
  assert_close(L.r2, 1.0, 1e-12);
  /* one row in the window: undefined */
  OK(intestine_measures_line(t, x, 50, 1.0, 1.05, 1e-9, &L));
  assert_int_equal(L.n, 1);
  assert_true(isnan(L.slope) && isnan(L.r2) && isnan(L.x0));
  /* a constant front: slope 0, fitted exactly */
  for (int i = 0; i < 50; i++)
    x[i] = 0.01;
  OK(intestine_measures_line(t, x, 50, 0.0, 4.9, 1e-9, &L));
  assert_close(L.slope, 0.0, 1e-15);
  assert_close(L.r2, 1.0, 0);
}

static void test_whole_waves(void **state) {
  (void)state;
  const double td = 0.05, Tw = 13.8, dt = 6e-6;
  assert_int_equal(intestine_measures_whole_waves(td + 3 * Tw - 0.4 * dt, td, Tw, 0, dt), 3);
  assert_int_equal(intestine_measures_whole_waves(td + 2.9 * Tw, td, Tw, 0, dt), 2);
  assert_int_equal(intestine_measures_whole_waves(td + 0.9 * Tw, td, Tw, 0, dt), 0);
  assert_int_equal(intestine_measures_whole_waves(td + 12.5 * Tw, td, Tw, 10, dt), 10);
  assert_int_equal(intestine_measures_whole_waves(0.01, td, Tw, 0, dt), 0);
}

/* rows every dt_out from 0 to t_end of x_F: still for the first wave (forward
 * by amp while pocket 0 squeezes, all of it back at the wave's end), then
 * climbing at u with the same pulse in every wave */
static int rows_fast_wave(double *t, double *x, double td, double Tw, double u, double amp,
                          double t_end, double dt_out) {
  int n = 0;
  for (double tt = 0; tt <= t_end + 1e-12 && n < NROWS; tt += dt_out, n++) {
    const double w = (tt - td) / Tw, ph = w - floor(w);
    const double pulse = tt < td ? 0 : amp * sin(M_PI * ph) * sin(M_PI * ph);
    const double climb = tt < td + Tw ? 0 : u * (tt - td - Tw);
    t[n] = tt;
    x[n] = 0.01 + climb + pulse;
  }
  return n;
}

static void test_front_whole_run(void **state) {
  (void)state;
  static double t[NROWS], x[NROWS];
  const double td = 0.05, Tw = 0.769, u = 0.0048, dt = 3e-6;
  /* 10 whole waves and half an eleventh, which must be left out */
  const int n = rows_fast_wave(t, x, td, Tw, u, 0.003, td + 10.5 * Tw, Tw / 120);
  intestine_front f;
  OK(intestine_measures_front(t, x, n, td, Tw, 0, 3, 0.99, dt, &f));
  assert_int_equal(f.waves, 10);
  double slope, r2;
  ls_reference(t, x, n, td, td + 10 * Tw, &slope, &r2);
  assert_close(f.line.slope, slope, 1e-9 * fabs(slope));
  assert_close(f.line.r2, r2, 1e-9);
  assert_close(f.line.t1, td + 10 * Tw, 1e-12);
  /* the whole run's slope is the climb's within its first, still wave: 9/10 u and more */
  assert_true(f.line.slope > 0.85 * u && f.line.slope < 1.1 * u);
  /* the first wave alone is not u_F: it only pulses */
  assert_true(fabs(f.first_wave.slope) < 0.1 * u);
  /* but the still first wave bends the line (R^2 0.987 < 0.99): the slope is not
   * constant, and u_F is the initial slope, over the first 3 waves */
  assert_true(f.line.r2 > 0.98 && f.line.r2 < 0.99);
  assert_true(f.from_initial);
  assert_close(f.u_F, f.initial.slope, 0);
  ls_reference(t, x, n, td, td + 3 * Tw, &slope, &r2);
  assert_close(f.u_F, slope, 1e-9 * fabs(slope));
  assert_close(f.initial.r2, r2, 1e-9);
  assert_true(f.u_F > 0.5 * u && f.u_F < 0.9 * u);
  assert_non_null(strstr(f.why, "initial slope over 3 wave"));
  assert_non_null(strstr(f.why, "10 waves does not fit"));
  /* the same rows without the still first wave: the line fits (R^2 >= 0.99) and is u_F */
  for (int i = 0; i < n; i++)
    if (t[i] >= td && t[i] < td + Tw)
      x[i] = 0.01 + u * (t[i] - td - Tw) + (x[i] - 0.01);
  OK(intestine_measures_front(t, x, n, td, Tw, 0, 3, 0.99, dt, &f));
  assert_true(f.line.r2 >= 0.99);
  assert_false(f.from_initial);
  ls_reference(t, x, n, td, td + 10 * Tw, &slope, &r2);
  assert_close(f.u_F, slope, 1e-9 * slope);
  assert_close(f.u_F, u, 0.02 * u);
  assert_non_null(strstr(f.why, "the line over 10 whole wave"));
  /* the schedule's 8 waves cap the window */
  OK(intestine_measures_front(t, x, n, td, Tw, 8, 3, 0.99, dt, &f));
  assert_int_equal(f.waves, 8);
  assert_close(f.line.t1, td + 8 * Tw, 1e-12);
}

static void test_front_stalls(void **state) {
  (void)state;
  static double t[NROWS], x[NROWS];
  const double td = 0.05, Tw = 13.8, u = 0.0005;
  int n = 0;
  for (double tt = 0; tt <= td + 10 * Tw + 1e-9; tt += 0.05, n++) {
    t[n] = tt;
    x[n] = 0.01 + u * fmin(fmax(tt - td, 0), 3 * Tw); /* climbs for 3 waves, then stalls */
  }
  intestine_front f;
  OK(intestine_measures_front(t, x, n, td, Tw, 10, 3, 0.99, 1e-5, &f));
  assert_int_equal(f.waves, 10);
  assert_true(f.line.r2 < 0.99);
  assert_true(f.from_initial);
  assert_close(f.u_F, u, 1e-9 * u);
  assert_close(f.initial.r2, 1.0, 1e-9);
  assert_close(f.initial.t1, td + 3 * Tw, 1e-12);
  assert_non_null(strstr(f.why, "initial slope"));
  /* a lower bar accepts the line (the whole run's mean climb, well below u) */
  OK(intestine_measures_front(t, x, n, td, Tw, 10, 3, 0.5, 1e-5, &f));
  assert_false(f.from_initial);
  assert_true(f.u_F < 0.6 * u);
}

static void test_front_no_whole_wave(void **state) {
  (void)state;
  double t[30], x[30];
  for (int i = 0; i < 30; i++) {
    t[i] = 0.01 * i;
    x[i] = 0.01 + 0.01 * t[i];
  }
  intestine_front f;
  OK(intestine_measures_front(t, x, 30, 0.02, 0.54, 0, 3, 0.99, 1e-5, &f));
  assert_int_equal(f.waves, 0);
  assert_true(isnan(f.u_F) && isnan(f.line.slope) && isnan(f.first_wave.slope));
  assert_non_null(strstr(f.why, "no whole wave"));
  /* bad arguments are errors */
  assert_int_equal(intestine_measures_front(t, x, 30, 0.02, 0.54, 0, 0, 0.99, 1e-5, &f),
                   PETSC_ERR_ARG_OUTOFRANGE);
}

static void test_at(void **state) {
  (void)state;
  const double t[] = {0, 0.5, 0.99999, 1.5}, a[] = {0, 0.1, 0.2, 0.3};
  double tr;
  assert_close(intestine_measures_at(t, a, 4, 1.0, 1e-4, &tr), 0.2, 0);
  assert_close(tr, 0.99999, 0);
  assert_close(intestine_measures_at(t, a, 4, 1.0, 1e-6, &tr), 0.3, 0);
  assert_true(isnan(intestine_measures_at(t, a, 4, 2.0, 1e-4, &tr)) && isnan(tr));
}

static void test_pumping_and_reynolds(void **state) {
  (void)state;
  double uP, uS;
  char why[96];
  intestine_measures_pumping(0.2, 0.0145, 10, &uP, &uS, why, sizeof(why));
  assert_close(uP, 0.25 * 0.0145 / 10, 1e-15);
  assert_close(uS, 0.2 * 0.0145, 1e-15);
  assert_string_equal(why, "");
  intestine_measures_pumping(0.0, 0.0145, 10, &uP, &uS, why, sizeof(why));
  assert_close(uP, 0.0, 0);
  assert_close(uS, 0.0, 0);
  intestine_measures_pumping(NAN, 0.0145, 10, &uP, &uS, why, sizeof(why));
  assert_true(isnan(uP) && isnan(uS));
  assert_non_null(strstr(why, "undefined"));
  intestine_measures_pumping(1.0, 0.0145, 10, &uP, &uS, why, sizeof(why));
  assert_true(isnan(uP));
  assert_close(uS, 0.0145, 1e-15);
  assert_non_null(strstr(why, "alpha = 1"));
  assert_close(intestine_measures_reynolds(0.02, 0.0048, 1e-6), 96.0, 1e-9);
  assert_true(isnan(intestine_measures_reynolds(0.02, -0.0054, 1e-6)));
  assert_true(isnan(intestine_measures_reynolds(0.02, 0.0, 1e-6)));
  assert_true(isnan(intestine_measures_reynolds(0.02, NAN, 1e-6)));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_line),
      cmocka_unit_test(test_whole_waves),
      cmocka_unit_test(test_front_whole_run),
      cmocka_unit_test(test_front_stalls),
      cmocka_unit_test(test_front_no_whole_wave),
      cmocka_unit_test(test_at),
      cmocka_unit_test(test_pumping_and_reynolds),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
