/* Pair arithmetic of the bond potentials, plain scalar functions (unit-tested
 * against finite-difference gradients of the energy).
 * d = x_i - x_j, r = |d|, x = r - r0. Each function returns fr with
 *   F_i = fr d,  F_j = -fr d,   fr = -U'(r)/r.
 * Harmonic (doc/theory.md):  U = K x^2,                     U'  = 2 K x
 * Nonlinear (doc/theory.md): U = k_b x^2/(L^2 - x^2),      U'  = 2 k_b L^2 x/(L^2 - x^2)^2
 *                     U'' = 2 k_b L^2 (L^2 + 3x^2)/(L^2 - x^2)^3  (stiffness for dt). */
#ifndef DMHS_BOND_IACT_H
#define DMHS_BOND_IACT_H
#include "virial_iact.h"
#include <math.h>

static inline double bond_harmonic_iact(double K, double r0, double r) {
  return -2.0 * K * (r - r0) / r;
}
static inline double bond_harmonic_energy(double K, double r0, double r) {
  return K * (r - r0) * (r - r0);
}

/* Valid for |x| < L only; callers check the stretch (bond_nonlinear.c). */
static inline double bond_nonlinear_iact(double kb, double r0, double L, double r) {
  const double x = r - r0, L2 = L * L, q = L2 - x * x;
  return -2.0 * kb * L2 * x / (q * q * r);
}
static inline double bond_nonlinear_energy(double kb, double r0, double L, double r) {
  const double x = r - r0;
  return kb * x * x / (L * L - x * x);
}
static inline double bond_nonlinear_stiffness(double kb, double L, double x) {
  const double L2 = L * L, q = L2 - x * x;
  return 2.0 * kb * L2 * (L2 + 3.0 * x * x) / (q * q * q);
}

/* A bond's force fr d (d = x_i - x_j) on both ends' accelerations, and its
 * virial: the loop body the bond laws share. */
static inline void bond_pair_apply(double (*restrict a)[2], double (*restrict W)[3],
                                   const double *restrict mass, PetscInt i, PetscInt j, double fr,
                                   const double d[2], int force, int virial) {
  if (force) {
    const double fi = fr / mass[i], fj = fr / mass[j];
    a[i][0] += fi * d[0];
    a[i][1] += fi * d[1];
    a[j][0] -= fj * d[0];
    a[j][1] -= fj * d[1];
  }
  if (virial)
    virial_pair_add(W, i, j, fr, d);
}

#endif
