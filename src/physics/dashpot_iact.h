/* Dashpots of the bonds and angles: Rayleigh dissipation R = gamma/2 q'^2 on a bond's
 * length q = r or an angle q = theta, so F_p = -gamma q' dq/dx_p. It damps each
 * bond's stretch and each angle's bend, not the body's translation or rotation
 * (q' = 0 there), and conserves momentum. gamma = 2 zeta sqrt(k I) gives the
 * isolated bond or angle the damping ratio zeta, with k = U''(q) and I the inertia
 * of q: 1/I = sum_p |dq/dx_p|^2/m_p (the reduced mass of a bond).
 * Why: a multiple-time-step scheme pumps the solids' fastest mode when the step
 * is near a resonance (doc/theory.md, "Dashpots of the bonds and angles"); a
 * zeta of 0.01 outgrows that pumping and barely touches the slow modes (their
 * damping ratio scales with their frequency over the bond's). */
#ifndef DMHS_DASHPOT_IACT_H
#define DMHS_DASHPOT_IACT_H
#include <math.h>

/* A bond i-j, d = x_i - x_j, r = |d|, dv = v_i - v_j: adds to fr (F_i = fr d). */
static inline double bond_dashpot_iact(double gamma, const double d[2], double r,
                                       const double dv[2]) {
  const double rdot = (dv[0] * d[0] + dv[1] * d[1]) / r;
  return -gamma * rdot / r;
}

/* gamma of a bond of stiffness k = U'' between masses mi, mj */
static inline double bond_dashpot_gamma(double zeta, double k, double mi, double mj) {
  return 2.0 * zeta * sqrt(k * mi * mj / (mi + mj));
}

/* An angle i-j-k at centre j, a = x_i - x_j, b = x_k - x_j, va = v_i - v_j,
 * vb = v_k - v_j: adds the dashpot's F_i and F_k to fi, fk (F_j = -(F_i + F_k)),
 * with gamma = 2 zeta sqrt(k_theta I), k_theta = U''(theta), masses mi, mj, mk.
 * dtheta/da and dtheta/db as angle_iact.h. */
static inline void angle_dashpot_iact(double zeta, double k_theta, double mi, double mj, double mk,
                                      const double a[2], const double b[2], const double va[2],
                                      const double vb[2], double fi[2], double fk[2]) {
  const double c = a[0] * b[1] - a[1] * b[0], sg = c >= 0.0 ? 1.0 : -1.0;
  const double ia2 = 1.0 / (a[0] * a[0] + a[1] * a[1]), ib2 = 1.0 / (b[0] * b[0] + b[1] * b[1]);
  const double ga[2] = {sg * a[1] * ia2, -sg * a[0] * ia2};
  const double gb[2] = {-sg * b[1] * ib2, sg * b[0] * ib2};
  const double gj[2] = {-(ga[0] + gb[0]), -(ga[1] + gb[1])};
  const double inv_inertia = ia2 / mi + ib2 / mk + (gj[0] * gj[0] + gj[1] * gj[1]) / mj;
  const double gamma = 2.0 * zeta * sqrt(k_theta / inv_inertia);
  const double thdot = ga[0] * va[0] + ga[1] * va[1] + gb[0] * vb[0] + gb[1] * vb[1];
  const double g = -gamma * thdot;
  fi[0] += g * ga[0];
  fi[1] += g * ga[1];
  fk[0] += g * gb[0];
  fk[1] += g * gb[1];
}

#endif
