/* Dashpots of the bonds and angles (dashpot_iact.h): the forces are -dR/dv of
 * R = gamma/2 q'^2 (finite differences in the velocities), sum to zero, vanish
 * for a rigid translation and rotation, dissipate -gamma q'^2; and an isolated
 * bond and angle, integrated as the solver does (kick-drift-kick, the dashpot
 * on the half-kicked velocity), decay at the damping ratio asked for. */
#include "solid_fixture.h"
#include "physics/bond_iact.h"
#include "physics/angle_iact.h"
#include "physics/dashpot_iact.h"

static const double zeta = 0.05, kb = 1e6, ka = 0.01, th0 = M_PI / 2;
static const double mass[3] = {2e-5, 3e-5, 1.5e-5};

/* angle dashpot forces on i, j, k at positions x, velocities v */
static void angle_forces(const double x[3][2], const double v[3][2], double f[3][2]) {
  const double a[2] = {x[0][0] - x[1][0], x[0][1] - x[1][1]},
               b[2] = {x[2][0] - x[1][0], x[2][1] - x[1][1]};
  const double va[2] = {v[0][0] - v[1][0], v[0][1] - v[1][1]},
               vb[2] = {v[2][0] - v[1][0], v[2][1] - v[1][1]};
  f[0][0] = f[0][1] = f[2][0] = f[2][1] = 0;
  angle_dashpot_iact(zeta, 2 * ka, mass[0], mass[1], mass[2], a, b, va, vb, f[0], f[2]);
  f[1][0] = -(f[0][0] + f[2][0]);
  f[1][1] = -(f[0][1] + f[2][1]);
}

/* theta' by finite differences of theta along the motion x + v t */
static double theta_rate(const double x[3][2], const double v[3][2]) {
  const double h = 1e-9;
  double th[2];
  for (int s = 0; s < 2; s++) {
    const double t = s ? h : -h;
    const double a[2] = {x[0][0] + t * v[0][0] - x[1][0] - t * v[1][0],
                         x[0][1] + t * v[0][1] - x[1][1] - t * v[1][1]};
    const double b[2] = {x[2][0] + t * v[2][0] - x[1][0] - t * v[1][0],
                         x[2][1] + t * v[2][1] - x[1][1] - t * v[1][1]};
    th[s] = angle_theta(a, b);
  }
  return (th[1] - th[0]) / (2 * h);
}

static void test_angle_dashpot_is_rayleigh(void **state) {
  (void)state;
  const double x[3][2] = {{1.2e-4, 0.3e-4}, {0, 0}, {-0.2e-4, 0.9e-4}};
  const double v[3][2] = {{0.01, -0.02}, {0.003, 0.004}, {-0.015, 0.007}};
  double f[3][2];
  angle_forces(x, v, f);
  /* gamma from the force's own dissipation: P = sum F.v = -gamma theta'^2 */
  const double thdot = theta_rate(x, v);
  double P = 0;
  for (int p = 0; p < 3; p++)
    P += f[p][0] * v[p][0] + f[p][1] * v[p][1];
  assert_true(P < 0);
  const double gamma = -P / (thdot * thdot);
  /* F_p = -dR/dv_p, R = gamma/2 theta'^2, theta' linear in v */
  for (int p = 0; p < 3; p++)
    for (int k = 0; k < 2; k++) {
      double vp[3][2], vm[3][2];
      memcpy(vp, v, sizeof(vp));
      memcpy(vm, v, sizeof(vm));
      const double dv = 1e-4;
      vp[p][k] += dv;
      vm[p][k] -= dv;
      const double rp = theta_rate(x, (const double(*)[2])vp),
                   rm = theta_rate(x, (const double(*)[2])vm);
      const double fd = -0.5 * gamma * (rp * rp - rm * rm) / (2 * dv);
      assert_true(fabs(f[p][k] - fd) <= 1e-5 * fabs(P / 0.01));
    }
  /* rigid translation and rotation: no force */
  const double omega = 7.0, u[2] = {0.02, -0.01};
  double vr[3][2], fr[3][2];
  for (int p = 0; p < 3; p++) {
    vr[p][0] = u[0] - omega * x[p][1];
    vr[p][1] = u[1] + omega * x[p][0];
  }
  angle_forces(x, (const double(*)[2])vr, fr);
  for (int p = 0; p < 3; p++)
    assert_true(fabs(fr[p][0]) + fabs(fr[p][1]) < 1e-12 * fabs(f[0][0]));
}

static void test_bond_dashpot_is_rayleigh(void **state) {
  (void)state;
  const double d[2] = {0.8e-4, -0.5e-4}, r = hypot(d[0], d[1]);
  const double dv[2] = {0.013, 0.021}, gamma = bond_dashpot_gamma(zeta, 2 * kb, 2e-5, 3e-5);
  const double fr = bond_dashpot_iact(gamma, d, r, dv);
  const double rdot = (d[0] * dv[0] + d[1] * dv[1]) / r;
  /* F_i = fr d = -gamma r' d/r; power -gamma r'^2 */
  assert_true(fabs(fr * (d[0] * dv[0] + d[1] * dv[1]) + gamma * rdot * rdot) <=
              1e-12 * gamma * rdot * rdot);
  /* rotation of the pair: dv perpendicular to d, no force */
  const double rot[2] = {-d[1] * 5.0, d[0] * 5.0};
  assert_true(fabs(bond_dashpot_iact(gamma, d, r, rot)) < 1e-12 * fabs(fr));
  assert_true(fabs(gamma - 2 * zeta * sqrt(2 * kb * 2e-5 * 3e-5 / 5e-5)) < 1e-12 * gamma);
}

/* peaks of |q - q_rest| over each half period: their ratio per period is exp(-2 pi
 * zeta/sqrt(1-zeta^2)) */
static double decay_per_period(const double *q, int n, double rest) {
  double first = 0, last = 0;
  int n_peaks = 0;
  for (int k = 1; k + 1 < n; k++) {
    const double a = q[k] - rest, b = q[k - 1] - rest, c = q[k + 1] - rest;
    if (a > 0 && a >= b && a > c) {
      if (!n_peaks)
        first = a;
      last = a;
      n_peaks++;
    }
  }
  assert_true(n_peaks >= 4);
  return pow(last / first, 1.0 / (n_peaks - 1));
}

#define N_STEPS 10000 /* 25 periods of 400 steps */

/* the bond's force on i: F_i = fr d */
static double bond_fr(const double x[2][2], const double v[2][2], double gamma, double d[2]) {
  d[0] = x[0][0] - x[1][0];
  d[1] = x[0][1] - x[1][1];
  const double r = hypot(d[0], d[1]), dv[2] = {v[0][0] - v[1][0], v[0][1] - v[1][1]};
  return bond_harmonic_iact(kb, 1e-4, r) + bond_dashpot_iact(gamma, d, r, dv);
}

static void test_bond_decays_at_zeta(void **state) {
  (void)state;
  const double m[2] = {2e-5, 3e-5}, r0 = 1e-4;
  const double mu = m[0] * m[1] / (m[0] + m[1]), omega = sqrt(2 * kb / mu);
  const double dt = 2 * M_PI / omega / 400, gamma = bond_dashpot_gamma(zeta, 2 * kb, m[0], m[1]);
  double x[2][2] = {{1.01e-4, 0}, {0, 0}}, v[2][2] = {{0, 0}, {0, 0}}, a[2][2], d[2];
  static double r[N_STEPS];
  double fr = bond_fr((const double(*)[2])x, (const double(*)[2])v, gamma, d);
  for (int s = 0; s < N_STEPS; s++) {
    for (int p = 0; p < 2; p++)
      for (int k = 0; k < 2; k++) {
        a[p][k] = (p ? -fr : fr) * d[k] / m[p];
        v[p][k] += 0.5 * dt * a[p][k];
        x[p][k] += dt * v[p][k];
      }
    /* the force at the new positions and the half-kicked velocities, as the solver has them */
    fr = bond_fr((const double(*)[2])x, (const double(*)[2])v, gamma, d);
    for (int p = 0; p < 2; p++)
      for (int k = 0; k < 2; k++)
        v[p][k] += 0.5 * dt * (p ? -fr : fr) * d[k] / m[p];
    r[s] = hypot(d[0], d[1]);
  }
  const double want = exp(-2 * M_PI * zeta / sqrt(1 - zeta * zeta));
  const double got = decay_per_period(r, N_STEPS, r0);
  print_message("bond: amplitude ratio per period %.5f, zeta %.3f wants %.5f\n", got, zeta, want);
  assert_true(fabs(got - want) < 0.01 * want);
}

/* the angle's forces on i, j, k: harmonic and dashpot */
static void angle_all_forces(const double x[3][2], const double v[3][2], double f[3][2]) {
  const double ra[2] = {x[0][0] - x[1][0], x[0][1] - x[1][1]},
               rb[2] = {x[2][0] - x[1][0], x[2][1] - x[1][1]};
  angle_forces(x, v, f);
  double fi[2], fk[2];
  angle_harmonic_iact(ka, th0, ra, rb, fi, fk);
  for (int k = 0; k < 2; k++) {
    f[0][k] += fi[k];
    f[2][k] += fk[k];
    f[1][k] -= fi[k] + fk[k];
  }
}

static void test_angle_decays_at_zeta(void **state) {
  (void)state;
  /* a right angle opened by 1e-3 rad, arms 1e-4 m, no bonds: to first order in the opening
   * theta is a damped oscillator of the inertia of dashpot_iact.h */
  const double L = 1e-4, d0 = 1e-3;
  double x[3][2] = {{L * cos(d0), -L * sin(d0)}, {0, 0}, {0, L}}, v[3][2] = {{0}}, f[3][2];
  static double th[N_STEPS];
  const double inertia =
      1 / (1 / (L * L * mass[0]) + 1 / (L * L * mass[2]) + 2 / (L * L * mass[1]));
  const double omega = sqrt(2 * ka / inertia), dt = 2 * M_PI / omega / 400;
  angle_all_forces((const double(*)[2])x, (const double(*)[2])v, f);
  for (int s = 0; s < N_STEPS; s++) {
    for (int p = 0; p < 3; p++)
      for (int k = 0; k < 2; k++) {
        v[p][k] += 0.5 * dt * f[p][k] / mass[p];
        x[p][k] += dt * v[p][k];
      }
    angle_all_forces((const double(*)[2])x, (const double(*)[2])v, f);
    for (int p = 0; p < 3; p++)
      for (int k = 0; k < 2; k++)
        v[p][k] += 0.5 * dt * f[p][k] / mass[p];
    const double ra[2] = {x[0][0] - x[1][0], x[0][1] - x[1][1]},
                 rb[2] = {x[2][0] - x[1][0], x[2][1] - x[1][1]};
    th[s] = angle_theta(ra, rb);
  }
  const double want = exp(-2 * M_PI * zeta / sqrt(1 - zeta * zeta));
  const double got = decay_per_period(th, N_STEPS, th0);
  print_message("angle: amplitude ratio per period %.5f, zeta %.3f wants %.5f\n", got, zeta, want);
  assert_true(fabs(got - want) < 0.02 * want);
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bond_dashpot_is_rayleigh),
      cmocka_unit_test(test_angle_dashpot_is_rayleigh),
      cmocka_unit_test(test_bond_decays_at_zeta),
      cmocka_unit_test(test_angle_decays_at_zeta),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
