/* Harmonic angle U = k_a (theta - theta0)^2 (doc/theory.md), for the angle i-j-k at
 * centre j, a = x_i - x_j, b = x_k - x_j. In 2D
 *   theta = atan2(|c|, a.b),  c = a_x b_y - a_y b_x   (in [0, pi]),
 *   dtheta/da = sgn(c) (a_y, -a_x)/|a|^2,  dtheta/db = sgn(c) (-b_y, b_x)/|b|^2,
 *   F_i = -U'(theta) dtheta/da,  F_k = -U'(theta) dtheta/db,  F_j = -(F_i + F_k).
 * atan2 keeps full precision near 0 and pi, where acos(a.b/|a||b|) and its
 * 1/sin(theta) derivative lose it (LAMMPS clips sin(theta) at 0.001 there).
 * At c = 0 exactly (straight or folded) sgn(c) = +1: U has a kink there unless
 * U'(theta) = 0, and either one-sided force is a valid choice. */
#ifndef DMHS_ANGLE_IACT_H
#define DMHS_ANGLE_IACT_H
#include <math.h>

static inline double angle_theta(const double a[2], const double b[2]) {
  const double c = a[0] * b[1] - a[1] * b[0];
  return atan2(fabs(c), a[0] * b[0] + a[1] * b[1]);
}

/* Returns U; writes F_i and F_k (F_j = -(F_i + F_k)). */
static inline double angle_harmonic_iact(double ka, double theta0, const double a[2],
                                         const double b[2], double fi[2], double fk[2]) {
  const double c = a[0] * b[1] - a[1] * b[0];
  const double theta = atan2(fabs(c), a[0] * b[0] + a[1] * b[1]);
  const double dth = theta - theta0;
  const double g = -2.0 * ka * dth * (c >= 0.0 ? 1.0 : -1.0); /* -U'(theta) sgn(c) */
  const double ia2 = 1.0 / (a[0] * a[0] + a[1] * a[1]), ib2 = 1.0 / (b[0] * b[0] + b[1] * b[1]);
  fi[0] = g * a[1] * ia2;
  fi[1] = -g * a[0] * ia2;
  fk[0] = -g * b[1] * ib2;
  fk[1] = g * b[0] * ib2;
  return ka * dth * dth;
}

#endif
