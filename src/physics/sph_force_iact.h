/* Pair arithmetic of the SPH momentum and continuity equations, as plain
 * scalar functions (unit-tested for antisymmetry).
 *
 * Momentum (Morris, Fox & Zhu 1997), for the pair term T with
 *   a_i += m_j T,  a_j -= m_i T   (so m_i a_i + m_j a_j = 0 exactly):
 *   T = -(p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij
 *       + (mu_i + mu_j)/(rho_i rho_j) (v_i - v_j) (1/r) dW/dr
 *       - Pi_ij grad_i W_ij                                   (optional)
 * with grad_i W_ij = dW/dr r_ij / r, r_ij = x_i - x_j, and the Monaghan (1992)
 * artificial viscosity, for v_ij . r_ij < 0 only:
 *   mu_ij = h v_ij . r_ij / (r^2 + eps^2), eps = 0.1 h,
 *   Pi_ij = (-alpha c0 mu_ij + beta mu_ij^2) / rho_bar,  rho_bar = (rho_i + rho_j)/2.
 *
 * Continuity: d rho_i/dt += m_j (v_i - v_j) . grad_i W_ij, and the same
 * scalar q = (v_i - v_j) . grad_i W_ij times m_i for j. */
#ifndef DMHS_SPH_FORCE_IACT_H
#define DMHS_SPH_FORCE_IACT_H
#include "sph_kernel.h"

/* Every pair function takes grad = (dW/dr)/r (sph_kernel_grad), so that
 * grad_i W_ij = grad r_ij. P = p / rho^2 and J = sqrt(mu_i + mu_j) / rho are
 * per-particle values computed once before the pair loop (sph_force.c; one liquid:
 * mu_i + mu_j = 2 rho0 nu, the same for every pair, so (mu_i + mu_j)/(rho_i rho_j)
 * = J_i J_j costs one multiply a pair instead of three). The operations are written
 * in the order the vectorised sweep (sph_force_cells.c) repeats lane by lane, so
 * both give the same bits. */
SPH_INLINE void sph_force_iact(const double rij[2], double grad, double P_i, double P_j, double J_i,
                               double J_j, const double vvisc_ij[2], double T[2]) {
  const double press = -(P_i + P_j);
  /* J_i * J_j is symmetric in i, j bit for bit, so T(j, i) == -T(i, j) exactly and sums do
   * not depend on which of the two is listed first (rank-count invariance, doc/parallel.md) */
  const double JJ = J_i * J_j;
  /* grad multiplies last: in the vectorised sweep the brackets are then computed while the
   * square root that grad waits for is still running (a shorter chain a pair) */
  T[0] = grad * (press * rij[0] + JJ * vvisc_ij[0]);
  T[1] = grad * (press * rij[1] + JJ * vvisc_ij[1]);
}

/* Adds the Monaghan term to T; vij is the (predicted) relative velocity, r2 = |r_ij|^2. */
SPH_INLINE void sph_force_iact_artificial_viscosity(const double rij[2], double r2, double grad,
                                                    double rho_i, double rho_j, const double vij[2],
                                                    double alpha, double beta, double c0, double h,
                                                    double T[2]) {
  const double vr = vij[0] * rij[0] + vij[1] * rij[1];
  if (vr >= 0.0)
    return;
  const double mu = h * vr / (r2 + 0.01 * h * h);
  const double Pi = (-alpha * c0 * mu + beta * mu * mu) / (0.5 * (rho_i + rho_j));
  const double pg = Pi * grad;
  T[0] -= pg * rij[0];
  T[1] -= pg * rij[1];
}

/* The continuity pair scalar q = (v_i - v_j) . grad_i W_ij. */
SPH_INLINE double sph_continuity_iact(const double rij[2], double grad, const double vij[2]) {
  return grad * (vij[0] * rij[0] + vij[1] * rij[1]);
}

/* Density diffusion (delta-SPH, Molteni & Colagrossi 2009, Comput. Phys.
 * Commun. 180:861) added to the continuity equation of liquid and solid pairs:
 *   d rho_i/dt += delta h_s c0 sum_j V_j psi_ij . grad_i W_ij,
 *   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / r^2,
 * i.e. + 2 delta h_s c0 V_j (rho_j - rho_i) (-dW/dr) / r. It damps the
 * density (acoustic) noise that the continuity equation otherwise keeps at
 * low viscosity, without a shear viscosity. Returns the pair scalar
 * D = 2 delta h_s c0 (rho_j - rho_i) (-grad): rho_i gains V_j D, rho_j loses V_i D. */
SPH_INLINE double sph_density_diffusion_iact(double grad, double rho_i, double rho_j,
                                             double delta_hs_c0) {
  return 2.0 * delta_hs_c0 * (rho_j - rho_i) * (-grad);
}

#endif
