/* Pair arithmetic of Monaghan's artificial pressure (J. J. Monaghan 2000, "SPH
 * without a tensile instability", J. Comput. Phys. 159:290), as plain scalar
 * functions (unit-tested for antisymmetry and direction).
 *
 * Under tension (p < 0) the SPH pressure term pulls neighbours together, and
 * with a kernel whose gradient vanishes at r = 0 (Lucy, the cubic spline) the
 * pull is strongest between particles that are already close: they pair up
 * and clump. Monaghan adds a short-range repulsion that grows as a pair closes:
 *   a_i += -sum_j m_j (R_i + R_j) f_ij^4 grad_i W_ij,  f_ij = W(r_ij) / W(dx),
 *   R_i = eps |p_i| / rho_i^2 where p_i < 0, else 0,
 * with dx the particle spacing at rest. At r = dx the term is eps times the
 * tension's own pull and it fades fast beyond; at rest (p >= 0) it is zero. */
#ifndef DMHS_SPH_TENSILE_IACT_H
#define DMHS_SPH_TENSILE_IACT_H
#include "sph_kernel.h"

/* R of one particle from P = p/rho^2 */
SPH_INLINE double sph_tensile_R(double eps, double P) {
  return P < 0.0 ? -eps * P : 0.0;
}

/* The pair term T (a_i += m_j T, a_j -= m_i T) for grad = (dW/dr)/r, w = W(r),
 * inv_w_dx = 1/W(dx) and R_sum = R_i + R_j. */
SPH_INLINE void sph_tensile_iact(const double rij[2], double grad, double w, double inv_w_dx,
                                 double R_sum, double T[2]) {
  const double f = w * inv_w_dx, f2 = f * f;
  const double s = -R_sum * (f2 * f2) * grad;
  T[0] = s * rij[0];
  T[1] = s * rij[1];
}

#endif
