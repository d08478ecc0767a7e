/* Harmonic angle: forces = -grad U (finite differences) on all three
 * particles, over the whole range of theta including near 0 and pi, for
 * several theta0; the three forces sum to zero. */
#include "solid_fixture.h"
#include "physics/angle_iact.h"

static double ka = 0.01, th0 = M_PI / 2;

static double U_of(const double x[3][2]) {
  const double a[2] = {x[0][0] - x[1][0], x[0][1] - x[1][1]},
               b[2] = {x[2][0] - x[1][0], x[2][1] - x[1][1]};
  const double d = angle_theta(a, b) - th0;
  return ka * d * d;
}

static void check_angle(double theta, double la, double lb, double rot) {
  double x[3][2] = {
      {la * cos(rot), la * sin(rot)}, {0, 0}, {lb * cos(rot + theta), lb * sin(rot + theta)}};
  for (int p = 0; p < 3; p++)
    x[p][0] += 0.3 * la, x[p][1] -= 0.7 * la; /* away from the origin */
  const double a[2] = {x[0][0] - x[1][0], x[0][1] - x[1][1]},
               b[2] = {x[2][0] - x[1][0], x[2][1] - x[1][1]};
  double f[3][2];
  const double U = angle_harmonic_iact(ka, th0, a, b, f[0], f[2]);
  f[1][0] = -(f[0][0] + f[2][0]);
  f[1][1] = -(f[0][1] + f[2][1]);
  assert_true(fabs(U - U_of((const double(*)[2])x)) <= 1e-14 + 1e-12 * U);
  assert_true(fabs(angle_theta(a, b) - fabs(theta)) < 1e-9);
  theta = fabs(theta);
  /* step well below the distance to the kink at 0 / pi */
  const double h = 1e-4 * PetscMin(PetscMin(theta, M_PI - theta), 1.0) * PetscMin(la, lb);
  const double scale = 2 * ka * M_PI / PetscMin(la, lb);
  for (int p = 0; p < 3; p++)
    for (int k = 0; k < 2; k++) {
      double xp[3][2], xm[3][2];
      memcpy(xp, x, sizeof(x));
      memcpy(xm, x, sizeof(x));
      xp[p][k] += h;
      xm[p][k] -= h;
      const double fd = -(U_of((const double(*)[2])xp) - U_of((const double(*)[2])xm)) / (2 * h);
      if (!(fabs(f[p][k] - fd) <= 1e-6 * scale))
        print_error("theta %g theta0 %g particle %d comp %d: F = %.12g, -dU/dx = %.12g\n", theta,
                    th0, p, k, f[p][k], fd);
      assert_true(fabs(f[p][k] - fd) <= 1e-6 * scale);
    }
  assert_true(fabs(f[0][0] + f[1][0] + f[2][0]) < 1e-15 * scale &&
              fabs(f[0][1] + f[1][1] + f[2][1]) < 1e-15 * scale);
}

static void test_angle_gradient(void **state) {
  (void)state;
  const double theta0s[] = {M_PI / 2, M_PI / 3, M_PI, 0.0, 2.0};
  const double thetas[] = {1e-3, 0.01, 0.3, 1.0, M_PI / 2, 2.0, 3.0, M_PI - 0.01, M_PI - 1e-3};
  for (size_t a = 0; a < sizeof(theta0s) / sizeof(theta0s[0]); a++) {
    th0 = theta0s[a];
    for (size_t t = 0; t < sizeof(thetas) / sizeof(thetas[0]); t++)
      for (int sgn = -1; sgn <= 1; sgn += 2) { /* both orientations (sign of the cross product) */
        check_angle(sgn * thetas[t], 1.0, 1.3, 0.4);
        check_angle(sgn * thetas[t], 1e-4, 0.7e-4, -2.0);
      }
  }
  th0 = M_PI / 2;
}

/* the 2D formula at 0 and pi exactly: finite, and U'(theta) = 0 at theta0 = pi gives zero force */
static void test_angle_degenerate(void **state) {
  (void)state;
  const double a[2] = {1, 0}, b[2] = {-2, 0}, c[2] = {3, 0};
  double fi[2], fk[2];
  const double U = angle_harmonic_iact(0.01, M_PI, a, b, fi, fk);
  assert_true(U == 0 && fi[0] == 0 && fi[1] == 0 && fk[0] == 0 && fk[1] == 0);
  (void)angle_harmonic_iact(0.01, M_PI / 2, a, c, fi, fk);
  assert_true(isfinite(fi[0]) && isfinite(fi[1]) && isfinite(fk[0]) && isfinite(fk[1]));
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_angle_gradient),
      cmocka_unit_test(test_angle_degenerate),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
