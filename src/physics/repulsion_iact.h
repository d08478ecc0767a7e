/* No-penetration repulsion (doc/theory.md) between a solid/wall and a fluid particle,
 * d = x_i - x_j, r = |d|, s = r* / r:
 *   F_i = K [s^p1 - s^p2] d / r^2   for r < r*, 0 beyond;   F_j = -F_i
 *   U   = K [(s^p1 - 1)/p1 - (s^p2 - 1)/p2]  (U(r*) = 0, F = -dU/dr d/r)
 * Stiffness at r*: -dF/dr = K (p1 - p2)/r*^2 (for the time-step limit). */
#ifndef DMHS_REPULSION_IACT_H
#define DMHS_REPULSION_IACT_H
#include <math.h>

/* s^p for a small positive integer p (unrolled when p is a constant) */
static inline double repulsion_ipow(double s, int p) {
  double r = 1.0;
  for (int k = 0; k < p; k++)
    r *= s;
  return r;
}

/* fr with F_i = fr d; r2 = r^2 (caller checks r2 < rstar^2) */
static inline double repulsion_iact(double K, double rstar, int p1, int p2, double r2) {
  const double s = rstar / sqrt(r2);
  return K * (repulsion_ipow(s, p1) - repulsion_ipow(s, p2)) / r2;
}

static inline double repulsion_energy(double K, double rstar, int p1, int p2, double r) {
  if (r >= rstar)
    return 0.0;
  const double s = rstar / r;
  return K * ((repulsion_ipow(s, p1) - 1.0) / p1 - (repulsion_ipow(s, p2) - 1.0) / p2);
}

#endif
