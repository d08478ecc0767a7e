/* Pair and per-particle arithmetic of the corrected SPH operators
 * (-sph_kernel_correction, doc/theory.md "Long-time accuracy"), as plain
 * scalar functions (unit-tested: exactness, bitwise pair-order symmetry).
 *
 * Why: on a particle set that is not a perfect lattice (a lattice sheared by
 * a curved velocity profile is enough) the plain SPH sums carry errors that
 * depend on the arrangement: sum_j V_j grad_i W_ij != 0, so a uniform
 * pressure p pushes a particle by ~p/(rho h) times that sum, and the Morris
 * Laplacian misses both its first moment (an error ~ grad v) and the exact
 * second moment (an error ~ the curvature). The corrections below make the
 * pressure gradient exact for linear p (zero for uniform p) and the viscous
 * term exact for quadratic v on any arrangement with a full support.
 *
 * Moments of particle i over its neighbours j (x = x_ij = x_i - x_j,
 * F = (dW/dr)/r, so grad_i W_ij = F x; V_j = m_j/rho_j; e = x (x) x/r^2 and
 * q = (x^2, 2xy, y^2), so that x.H x = q.h for h = (H_xx, H_xy, H_yy)):
 *   M_i = sum_j V_j F x (x) x           (= -I in the continuum)
 *   g_i = sum_j V_j F (v_j - v_i) (x) x (raw velocity gradient)
 *   A_i = sum_j V_j F e (x) q           (4th moment; 5 distinct entries)
 *   R_i = sum_j V_j F e (x) x,  Q_i = sum_j V_j F x (x) q   (3rd moments; 4 each)
 * Per particle (Bonet & Lok 1999; Fatehi & Manzari 2011):
 *   L_i = -M_i^-1      corrected gradient: grad_i W -> L_i grad_i W
 *   G_i = g_i L_i      velocity gradient, G_ab = d v_a/d x_b, exact for linear v;
 *                      for quadratic v it is off by (1/2) L_i Q_i h
 *   S_i = sum_j V_j 2F e (v_i - v_j - G_i x) = -(A_i + R_i L_i Q_i) h   (quadratic v)
 *   beta_i: -(A_i + R_i L_i Q_i)^T beta_i = (1, 0, 1), so that beta_i . S_i = lap v
 *           (beta = (B_xx, 2 B_xy, B_yy); the R L Q term vanishes on symmetric
 *           arrangements such as a lattice, and is what makes the Laplacian
 *           exact on a disordered one)
 * and the pair terms (a_i += m_j T, a_j += m_i T' with T' from j's tensors):
 *   pressure:  T = -(p_j - p_i)/(rho_i rho_j) F L_i x        (-(1/rho_i) grad p_i)
 *   viscous:   T = 2 nu/rho_j F (x.B_i x/r^2) (v_i - v_j - G_i x)        (nu lap v_i)
 * Neither is antisymmetric in the pair: momentum is not conserved to round-off.
 *
 * The continuity equation takes the corrected divergence, d rho_i/dt = -rho_i div_i,
 * div_i = tr(g'_i L_i) with g' the raw gradient of the divergence velocities
 * (g plus the walls' share gw of the difference v_div - v_visc):
 * the plain sum_j m_j v_ij . grad_i W_ij is the time derivative of the summation
 * density, which follows the lattice's arrangement as it shears (a drift of the
 * mean density that changes nu = mu/rho), while div_i vanishes for every
 * divergence-free linear field. The divergence velocity is v_visc for the
 * liquid and a wall's own velocity, as in the plain continuity equation: with
 * the quadratic wall extrapolation (sph_wall.c) in the divergence an acoustic
 * mode grew at the wall (the quick channel at c0 = 0.1 m/s blew up at
 * t = 0.26 s, and at 0.12 s with only its normal part removed). */
#ifndef DMHS_SPH_CORRECTION_IACT_H
#define DMHS_SPH_CORRECTION_IACT_H
#include "sph_kernel.h"

/* Determinants below these fractions of their continuum values (det(-M) = 1,
 * det(-A) = 1/4) mean a neighbourhood too sparse or one-sided to correct: the
 * particle then falls back to the plain operators (L = I, G = 0, B = I). */
#define SPH_CORRECTION_MIN_DET_M 0.1
#define SPH_CORRECTION_MIN_DET_T 0.025

typedef struct {
  double g[4];  /* (v_j - v_i)_a F x_b: xx, xy, yx, yy */
  double gw[4]; /* the same with e = v_div - v_visc (non-zero on walls only) */
  double T[5];  /* A's entries: F x^4, x^3 y, x^2 y^2, x y^3, y^4 (over r^2); M from them */
  double R[4];  /* F x^3, x^2 y, x y^2, y^3 over r^2 */
  double Q[4];  /* F x^3, x^2 y, x y^2, y^3 */
} sph_moments;

typedef struct {
  double L[3]; /* symmetric: xx, xy, yy */
  double G[4]; /* d v_a/d x_b: xx, xy, yx, yy */
  double B[3]; /* symmetric: xx, xy, yy */
  double div;  /* div v = tr(g' L) (the plain SPH divergence where the correction falls back) */
} sph_correction;

/* Adds neighbour j's share to i's moments: x = x_i - x_j, F = (dW/dr)/r,
 * inv_r2 = 1/r^2, vji = v_j - v_i (viscous velocities), V_j = m_j/rho_j.
 * Called for j with -x, -vji and V_i: the products are then bitwise those of
 * the pair listed the other way round. M = sum V F x (x) x needs no sums of
 * its own: x^2 = x^2 (x^2 + y^2)/r^2, so M = (T0 + T2, T1 + T3, T2 + T4). */
SPH_INLINE void sph_moments_pair(const double x[2], double F, double inv_r2, const double vji[2],
                                 double V_j, sph_moments *m) {
  const double f = V_j * F, fr2 = f * inv_r2;
  const double xx = x[0] * x[0], xy = x[0] * x[1], yy = x[1] * x[1];
  m->g[0] += f * (vji[0] * x[0]);
  m->g[1] += f * (vji[0] * x[1]);
  m->g[2] += f * (vji[1] * x[0]);
  m->g[3] += f * (vji[1] * x[1]);
  m->T[0] += fr2 * (xx * xx);
  m->T[1] += fr2 * (xx * xy);
  m->T[2] += fr2 * (xx * yy);
  m->T[3] += fr2 * (xy * yy);
  m->T[4] += fr2 * (yy * yy);
  const double c[4] = {xx * x[0], xx * x[1], yy * x[0], yy * x[1]}; /* odd: flip with x */
  m->R[0] += fr2 * c[0];
  m->R[1] += fr2 * c[1];
  m->R[2] += fr2 * c[2];
  m->R[3] += fr2 * c[3];
  m->Q[0] += f * c[0];
  m->Q[1] += f * c[1];
  m->Q[2] += f * c[2];
  m->Q[3] += f * c[3];
}

/* The divergence's share of a pair with a wall: eji = e_j - e_i, e = v_div - v_visc
 * (zero on liquid rows, so only pairs with a wall need it). */
SPH_INLINE void sph_moments_pair_wall(const double x[2], double F, const double eji[2], double V_j,
                                      sph_moments *m) {
  const double f = V_j * F;
  m->gw[0] += f * (eji[0] * x[0]);
  m->gw[1] += f * (eji[0] * x[1]);
  m->gw[2] += f * (eji[1] * x[0]);
  m->gw[3] += f * (eji[1] * x[1]);
}

/* The plain operators: difference-form pressure gradient, Morris viscosity and
 * the plain divergence -sum_j V_j v_ij . grad_i W_ij (the trace of g). */
SPH_INLINE void sph_correction_identity(const sph_moments *m, sph_correction *c) {
  *c = (sph_correction){.L = {1.0, 0.0, 1.0},
                        .G = {0.0, 0.0, 0.0, 0.0},
                        .B = {1.0, 0.0, 1.0},
                        .div = (m->g[0] + m->gw[0]) + (m->g[3] + m->gw[3])};
}

/* Solves K b = rhs (3 x 3) by Cramer's rule; returns det K. */
SPH_INLINE double sph_correction_solve3(const double K[3][3], const double rhs[3], double b[3]) {
  const double det = K[0][0] * (K[1][1] * K[2][2] - K[1][2] * K[2][1]) -
                     K[0][1] * (K[1][0] * K[2][2] - K[1][2] * K[2][0]) +
                     K[0][2] * (K[1][0] * K[2][1] - K[1][1] * K[2][0]);
  const double inv = 1.0 / det;
  for (int k = 0; k < 3; k++) {
    double C[3][3];
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++)
        C[a][c] = c == k ? rhs[a] : K[a][c];
    b[k] = inv * (C[0][0] * (C[1][1] * C[2][2] - C[1][2] * C[2][1]) -
                  C[0][1] * (C[1][0] * C[2][2] - C[1][2] * C[2][0]) +
                  C[0][2] * (C[1][0] * C[2][1] - C[1][1] * C[2][0]));
  }
  return det;
}

/* L, G and B from the moments; returns 0 when the neighbourhood is too sparse
 * (c is then the identity). */
SPH_INLINE int sph_correction_from_moments(const sph_moments *m, sph_correction *c) {
  const double M[3] = {m->T[0] + m->T[2], m->T[1] + m->T[3], m->T[2] + m->T[4]};
  const double detM = M[0] * M[2] - M[1] * M[1]; /* det(-M) = det(M) in 2D */
  if (!(detM > SPH_CORRECTION_MIN_DET_M)) {
    sph_correction_identity(m, c);
    return 0;
  }
  const double s = -1.0 / detM; /* L = -M^-1 */
  const double L[3] = {s * M[2], -s * M[1], s * M[0]};
  /* A' = A + R L Q (rows e_xx, e_xy, e_yy; columns q_xx, q_xy, q_yy) */
  const double *t = m->T, *r = m->R, *q = m->Q;
  const double Rm[3][2] = {{r[0], r[1]}, {r[1], r[2]}, {r[2], r[3]}};
  const double Qm[2][3] = {{q[0], 2.0 * q[1], q[2]}, {q[1], 2.0 * q[2], q[3]}};
  const double Lm[2][2] = {{L[0], L[1]}, {L[1], L[2]}};
  double LQ[2][3], K[3][3]; /* K = -(A')^T */
  for (int a = 0; a < 2; a++)
    for (int l = 0; l < 3; l++)
      LQ[a][l] = Lm[a][0] * Qm[0][l] + Lm[a][1] * Qm[1][l];
  const double A[3][3] = {
      {t[0], 2.0 * t[1], t[2]}, {t[1], 2.0 * t[2], t[3]}, {t[2], 2.0 * t[3], t[4]}};
  for (int k = 0; k < 3; k++)
    for (int l = 0; l < 3; l++)
      K[l][k] = -(A[k][l] + Rm[k][0] * LQ[0][l] + Rm[k][1] * LQ[1][l]);
  const double rhs[3] = {1.0, 0.0, 1.0};
  double beta[3];
  const double detK = sph_correction_solve3(K, rhs, beta); /* det(-A'^T) = 1/4 in the continuum */
  if (!(detK > SPH_CORRECTION_MIN_DET_T)) {
    sph_correction_identity(m, c);
    return 0;
  }
  c->L[0] = L[0];
  c->L[1] = L[1];
  c->L[2] = L[2];
  c->G[0] = m->g[0] * L[0] + m->g[1] * L[1];
  c->G[1] = m->g[0] * L[1] + m->g[1] * L[2];
  c->G[2] = m->g[2] * L[0] + m->g[3] * L[1];
  c->G[3] = m->g[2] * L[1] + m->g[3] * L[2];
  c->B[0] = beta[0];
  c->B[1] = 0.5 * beta[1];
  c->B[2] = beta[2];
  const double gd[4] = {m->g[0] + m->gw[0], m->g[1] + m->gw[1], m->g[2] + m->gw[2],
                        m->g[3] + m->gw[3]};
  c->div = (gd[0] * L[0] + gd[1] * L[1]) + (gd[2] * L[1] + gd[3] * L[2]);
  return 1;
}

/* The corrected pressure and viscous pair term seen from i (a_i += m_j T):
 * x = x_i - x_j, F = (dW/dr)/r, inv_r2 = 1/r^2, dp = p_j - p_i, vv = v_visc_i - v_visc_j,
 * inv_rho2 = 1/(rho_i rho_j), nu2_rho = 2 nu/rho_j, c = i's correction. The term for j
 * is this call with -x, -dp, -vv, 2 nu/rho_i and j's correction.
 * The viscous term is nu lap v with the kinematic viscosity itself, where the
 * plain form has mu/rho_i = rho0 nu/rho_i: the density estimate carries errors
 * of the particle arrangement (summation density on the channel's lattice is
 * 0.29 % above rho0 with Lucy at h = 3 dx) that would change the viscosity by
 * as much, while a weakly compressible liquid's density differs from rho0 by
 * O(Mach^2) only. */
SPH_INLINE void sph_corrected_iact(const double x[2], double F, double inv_r2, double dp,
                                   double inv_rho2, const double vv[2], double nu2_rho,
                                   const sph_correction *c, double T[2]) {
  const double Lx[2] = {c->L[0] * x[0] + c->L[1] * x[1], c->L[1] * x[0] + c->L[2] * x[1]};
  const double press = -dp * inv_rho2 * F;
  const double w =
      (c->B[0] * (x[0] * x[0]) + 2.0 * c->B[1] * (x[0] * x[1]) + c->B[2] * (x[1] * x[1])) * inv_r2;
  const double visc = nu2_rho * F * w;
  const double du[2] = {vv[0] - (c->G[0] * x[0] + c->G[1] * x[1]),
                        vv[1] - (c->G[2] * x[0] + c->G[3] * x[1])};
  T[0] = press * Lx[0] + visc * du[0];
  T[1] = press * Lx[1] + visc * du[1];
}

#endif
