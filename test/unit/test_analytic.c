/* Series solutions of start-up Poiseuille and Couette flow (src/diag/analytic.c),
 * walls at y = 0 and l. Proves:
 *   - Poiseuille: for large t the series gives the steady parabola F/(2 nu) y (l - y);
 *     for t -> 0+ (t = 1e-6 l^2/nu) the interior, away from the walls, still moves as
 *     a free liquid, v = F t (~1e-5 of the steady peak);
 *   - Couette: for large t the steady profile V y/l; at t -> 0+ the interior is at
 *     rest; at every t > 0 the wall values are 0 and V;
 *   - both satisfy the PDE dv/dt = nu d2v/dy2 (+ F) at interior points and times,
 *     checked by finite differences to 1e-4 of the terms' scale. */
#include "unit_common.h"
#include "dmhs/analytic.h"

static const double l = 1.3e-3, nu = 1.1e-6, F = 2.5e-4, V = 1.7e-3;
#define T_DIFF (l * l / nu) /* diffusion time */

static double pois(double y, double t) { return analytic_poiseuille(y, t, F, nu, l); }
static double cou(double y, double t) { return analytic_couette(y, t, V, nu, l); }

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

/* Residual of v_t - nu v_yy - f at interior (y, t), relative to the larger of scale and
 * the terms themselves. */
static void check_pde(double (*v)(double, double), double f, double scale, double tol) {
  const double ts[] = {0.003 * T_DIFF, 0.02 * T_DIFF, 0.1 * T_DIFF, 0.4 * T_DIFF};
  const double ys[] = {0.1 * l, 0.27 * l, 0.5 * l, 0.73 * l, 0.9 * l};
  for (int a = 0; a < 4; a++)
    for (int b = 0; b < 5; b++) {
      const double t = ts[a], y = ys[b], dt = 1e-3 * t, dy = 2.5e-4 * l;
      const double v_t = (v(y, t + dt) - v(y, t - dt)) / (2.0 * dt);
      const double v_yy = (v(y + dy, t) - 2.0 * v(y, t) + v(y - dy, t)) / (dy * dy);
      const double res = v_t - nu * v_yy - f;
      const double size = fmax(scale, fmax(fabs(v_t), fabs(nu * v_yy)));
      if (fabs(res) > tol * size)
        fail_msg("PDE residual %g at y/l = %g, t nu/l^2 = %g (v_t %g, nu v_yy %g, f %g)", res,
                 y / l, t / T_DIFF, v_t, nu * v_yy, f);
    }
}

static void test_poiseuille_pde(void **state) {
  (void)state;
  check_pde(pois, F, F, 1e-4);
}

static void test_couette_pde(void **state) {
  (void)state;
  /* v_t is of order V nu / l^2 * exp(-pi^2 nu t/l^2); that is the scale */
  check_pde(cou, 0.0, V * nu / (l * l), 1e-4);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_poiseuille_limits),
      cmocka_unit_test(test_couette_limits),
      cmocka_unit_test(test_poiseuille_pde),
      cmocka_unit_test(test_couette_pde),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
