/* Series solutions of start-up Poiseuille, Couette and Womersley flow
 * (src/diag/analytic.c), walls at y = 0 and l. Proves:
 *   - Poiseuille: for large t the series gives the steady parabola F/(2 nu) y (l - y);
 *     for t -> 0+ (t = 1e-6 l^2/nu) the interior, away from the walls, still moves as
 *     a free liquid, v = F t (~1e-5 of the steady peak);
 *   - Couette: for large t the steady profile V y/l; at t -> 0+ the interior is at
 *     rest; at every t > 0 the wall values are 0 and V;
 *   - both satisfy the PDE dv/dt = nu d2v/dy2 (+ F) at interior points and times,
 *     checked by finite differences to 1e-4 of the terms' scale;
 *   - Womersley (g0 sin(w t) from rest): at large t the start-up series equals the
 *     steady-periodic complex solution to 1e-10 of its centreline amplitude (at three
 *     Womersley numbers), which is the maximum of the centreline speed over a period
 *     and tends to the quasi-steady g0 a^2/(2 nu) at low frequency; v = 0 at t = 0
 *     and on the walls; at t -> 0+ the interior moves as a free liquid,
 *     v = g0 (1 - cos wt)/w; dv/dt - nu d2v/dy2 = g0 sin wt by finite differences. */
#include "unit_common.h"
#include "dmhs/analytic.h"

static const double l = 1.3e-3, nu = 1.1e-6, F = 2.5e-4, V = 1.7e-3;
#define T_DIFF (l * l / nu) /* diffusion time */
/* Womersley number a sqrt(w/nu) of the vein case, a = l/2 */
static const double g0 = 3.1e-3, wo_vein = 2.76;
#define OMEGA(wo) ((wo) * (wo)*nu / (0.25 * l * l))

static double pois(double y, double t) {
  return analytic_poiseuille(y, t, F, nu, l);
}
static double cou(double y, double t) {
  return analytic_couette(y, t, V, nu, l);
}
static double wom(double y, double t) {
  return analytic_womersley(y, t, g0, OMEGA(wo_vein), nu, l);
}

static void test_poiseuille_limits(void **state) {
  (void)state;
  const double peak = F * l * l / (8.0 * nu);
  for (int i = 0; i <= 20; i++) {
    const double y = i / 20.0 * l;
    assert_close(pois(y, 5.0 * T_DIFF), F / (2.0 * nu) * y * (l - y), 1e-10 * peak);
  }
  const double t = 1e-6 * T_DIFF; /* diffusion length sqrt(nu t) = 1e-3 l */
  for (int i = 1; i < 20; i++) {
    const double y = i / 20.0 * l;
    assert_close(pois(y, t), F * t, 1e-6 * F * t);
    assert_true(fabs(pois(y, t)) < 1e-4 * peak);
  }
  /* no slip at both walls at every time */
  const double times[] = {1e-6 * T_DIFF, 1e-3 * T_DIFF, 0.05 * T_DIFF, T_DIFF};
  for (int k = 0; k < 4; k++) {
    assert_close(pois(0.0, times[k]), 0.0, 1e-12 * peak);
    assert_close(pois(l, times[k]), 0.0, 1e-12 * peak);
  }
}

static void test_couette_limits(void **state) {
  (void)state;
  for (int i = 0; i <= 20; i++) {
    const double y = i / 20.0 * l;
    assert_close(cou(y, 5.0 * T_DIFF), V * y / l, 1e-10 * V);
  }
  for (int i = 0; i < 19; i++) { /* up to 0.9 l: 100 diffusion lengths from the moving wall */
    const double y = i / 20.0 * l;
    assert_close(cou(y, 1e-6 * T_DIFF), 0.0, 1e-10 * V);
  }
  const double times[] = {1e-6 * T_DIFF, 1e-3 * T_DIFF, 0.05 * T_DIFF, T_DIFF};
  for (int k = 0; k < 4; k++) {
    assert_close(cou(0.0, times[k]), 0.0, 1e-10 * V);
    assert_close(cou(l, times[k]), V, 1e-10 * V);
  }
}

/* Residual of v_t - nu v_yy - f(t) at interior (y, t), relative to the larger of scale
 * and the terms themselves; the time step of the difference is 1e-3 t, at most dt_max. */
static void check_pde(double (*v)(double, double), double (*f)(double), double scale, double tol,
                      double dt_max) {
  const double ts[] = {0.003 * T_DIFF, 0.02 * T_DIFF, 0.1 * T_DIFF, 0.4 * T_DIFF};
  const double ys[] = {0.1 * l, 0.27 * l, 0.5 * l, 0.73 * l, 0.9 * l};
  for (int a = 0; a < 4; a++)
    for (int b = 0; b < 5; b++) {
      const double t = ts[a], y = ys[b], dt = fmin(1e-3 * t, dt_max), dy = 2.5e-4 * l;
      const double v_t = (v(y, t + dt) - v(y, t - dt)) / (2.0 * dt);
      const double v_yy = (v(y + dy, t) - 2.0 * v(y, t) + v(y - dy, t)) / (dy * dy);
      const double res = v_t - nu * v_yy - f(t);
      const double size = fmax(scale, fmax(fabs(v_t), fabs(nu * v_yy)));
      if (fabs(res) > tol * size)
        fail_msg("PDE residual %g at y/l = %g, t nu/l^2 = %g (v_t %g, nu v_yy %g, f %g)", res,
                 y / l, t / T_DIFF, v_t, nu * v_yy, f(t));
    }
}

static double force_poiseuille(double t) {
  (void)t;
  return F;
}
static double force_none(double t) {
  (void)t;
  return 0.0;
}
static double force_womersley(double t) {
  return g0 * sin(OMEGA(wo_vein) * t);
}

static void test_poiseuille_pde(void **state) {
  (void)state;
  check_pde(pois, force_poiseuille, F, 1e-4, INFINITY);
}

static void test_couette_pde(void **state) {
  (void)state;
  /* v_t is of order V nu / l^2 * exp(-pi^2 nu t/l^2); that is the scale */
  check_pde(cou, force_none, V * nu / (l * l), 1e-4, INFINITY);
}

/* Large t: the start-up transient exp(-beta_0 t) is below 1e-20, and what is left is the
 * steady-periodic solution, at every phase and height, for a low, the vein's and a high
 * Womersley number. */
static void test_womersley_periodic_limit(void **state) {
  (void)state;
  const double wos[] = {0.5, wo_vein, 8.0};
  for (int k = 0; k < 3; k++) {
    const double w = OMEGA(wos[k]), amp = analytic_womersley_amplitude(g0, w, nu, l);
    const double t0 = 5.0 * T_DIFF, period = 2.0 * M_PI / w; /* exp(-pi^2 nu t0/l^2) ~ 4e-22 */
    for (int j = 0; j < 16; j++)
      for (int i = 0; i <= 20; i++) {
        const double t = t0 + j * period / 16.0, y = i / 20.0 * l;
        const double series = analytic_womersley(y, t, g0, w, nu, l);
        const double periodic = analytic_womersley_periodic(y, t, g0, w, nu, l);
        if (!(fabs(series - periodic) <= 1e-10 * amp))
          fail_msg("Wo %g, y/l %g, phase %d/16: series %.17g, periodic %.17g, diff %.3e of the "
                   "amplitude",
                   wos[k], y / l, j, series, periodic, fabs(series - periodic) / amp);
      }
  }
}

/* The normalisation: the steady-periodic centreline speed peaks at the amplitude once a
 * period; at low frequency it is the quasi-steady Poiseuille peak g0 a^2/(2 nu). */
static void test_womersley_amplitude(void **state) {
  (void)state;
  const double wos[] = {0.5, wo_vein, 8.0};
  for (int k = 0; k < 3; k++) {
    const double w = OMEGA(wos[k]), amp = analytic_womersley_amplitude(g0, w, nu, l);
    double peak = 0.0;
    for (int j = 0; j < 4000; j++)
      peak = fmax(peak,
                  analytic_womersley_periodic(0.5 * l, j * 2.0 * M_PI / (4000 * w), g0, w, nu, l));
    assert_close(peak, amp, 1e-6 * amp); /* the grid's phase error: (pi/4000)^2/2 */
    assert_true(amp > 0 && amp < g0 / w * 1.2);
  }
  const double w = OMEGA(0.05), a = 0.5 * l;
  assert_close(analytic_womersley_amplitude(g0, w, nu, l), g0 * a * a / (2.0 * nu),
               1e-4 * g0 * a * a / (2.0 * nu));
  /* the sign of g0 changes the phase, not the scale */
  assert_close(analytic_womersley_amplitude(-g0, w, nu, l),
               analytic_womersley_amplitude(g0, w, nu, l), 1e-15 * g0 * a * a / nu);
}

/* From rest: 0 at t = 0 (the rearranged series must cancel to round-off), 0 on the walls
 * at every t, and at t -> 0+ (diffusion length 1e-2 l) the interior, 10 diffusion lengths
 * or more from the walls, is a free liquid under g0 sin wt: v = g0 (1 - cos wt)/w. */
static void test_womersley_start(void **state) {
  (void)state;
  const double w = OMEGA(wo_vein), amp = analytic_womersley_amplitude(g0, w, nu, l);
  for (int i = 0; i <= 20; i++) {
    const double y = i / 20.0 * l;
    assert_close(analytic_womersley(y, 0.0, g0, w, nu, l), 0.0, 1e-12 * amp);
    assert_close(analytic_womersley(y, -1.0, g0, w, nu, l), 0.0, 0.0);
  }
  const double t = 1e-4 * T_DIFF, free = g0 * (1.0 - cos(w * t)) / w;
  for (int i = 2; i <= 18; i++) {
    const double y = i / 20.0 * l;
    assert_close(wom(y, t), free, 1e-6 * free);
  }
  const double times[] = {1e-4 * T_DIFF, 0.05 * T_DIFF, 0.3 * T_DIFF, 2.0 * T_DIFF};
  for (int k = 0; k < 4; k++) {
    assert_close(wom(0.0, times[k]), 0.0, 1e-12 * amp);
    assert_close(wom(l, times[k]), 0.0, 1e-12 * amp);
  }
}

static void test_womersley_pde(void **state) {
  (void)state;
  /* the time step of the difference at most 1e-5 of a period: error (2 pi 1e-5)^2/6 */
  check_pde(wom, force_womersley, g0, 1e-6, 1e-5 * 2.0 * M_PI / OMEGA(wo_vein));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_poiseuille_limits),        cmocka_unit_test(test_couette_limits),
      cmocka_unit_test(test_poiseuille_pde),           cmocka_unit_test(test_couette_pde),
      cmocka_unit_test(test_womersley_periodic_limit), cmocka_unit_test(test_womersley_amplitude),
      cmocka_unit_test(test_womersley_start),          cmocka_unit_test(test_womersley_pde),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
