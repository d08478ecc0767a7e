/* SPH kernels with support radius h (W = 0 for r >= h, LAMMPS convention),
 * normalised in 1, 2 and 3 dimensions. q = r / h.
 *
 *   Lucy (1977):         W = a_d (1 + 3q)(1 - q)^3,
 *                        a_1 = 5/(4h), a_2 = 5/(pi h^2), a_3 = 105/(16 pi h^3)
 *   Cubic B-spline (Monaghan & Lattanzio 1985) with smoothing length s = h/2,
 *                        u = r/s = 2q: W = sigma_d / s^d * {1 - 1.5u^2 + 0.75u^3 (u < 1);
 *                        0.25 (2 - u)^3 (1 <= u < 2)}, sigma = 2/3, 10/(7 pi), 1/pi
 *   Wendland C2 (1995):  1D W = 5/(4h) (1 - q)^3 (1 + 3q);
 *                        2D/3D W = b_d (1 - q)^4 (1 + 4q), b_2 = 7/(pi h^2), b_3 = 21/(2 pi h^3)
 *
 * Callers pass the kind and dimension as compile-time constants so that the
 * switch folds away inside specialised sweeps. */
#ifndef DMHS_SPH_KERNEL_H
#define DMHS_SPH_KERNEL_H
#include <math.h>
#include "dmhs/sph.h"

#define SPH_INLINE static inline __attribute__((always_inline))

SPH_INLINE double sph_kernel_norm(sph_kernel_kind kind, int dim, double h) {
  const double pi = M_PI;
  switch (kind) {
  case SPH_KERNEL_LUCY:
    return dim == 1   ? 5.0 / (4.0 * h)
           : dim == 2 ? 5.0 / (pi * h * h)
                      : 105.0 / (16.0 * pi * h * h * h);
  case SPH_KERNEL_CUBIC: {
    const double s = 0.5 * h;
    return dim == 1   ? 2.0 / (3.0 * s)
           : dim == 2 ? 10.0 / (7.0 * pi * s * s)
                      : 1.0 / (pi * s * s * s);
  }
  case SPH_KERNEL_WENDLAND:
    return dim == 1   ? 5.0 / (4.0 * h)
           : dim == 2 ? 7.0 / (pi * h * h)
                      : 21.0 / (2.0 * pi * h * h * h);
  }
  return 0.0;
}

/* Coincident particles (a pair that clumped at a free surface, r = 0): dW/dr / r
 * is finite there for every kernel but computes as 0/0. The pair loops take
 * r^2 no smaller than this fraction of h^2, far below any real separation, so
 * every other pair is untouched bit for bit. */
#define SPH_R2_FLOOR 1e-18

/* W(r) and dW/dr for r < h (r >= h gives 0). Takes 1/h: the hot loops then
 * multiply instead of divide. */
SPH_INLINE void sph_kernel_eval(sph_kernel_kind kind, int dim, double norm, double inv_h, double r,
                                double *w, double *dwdr) {
  const double q = r * inv_h;
  if (q >= 1.0) {
    *w = 0.0;
    *dwdr = 0.0;
    return;
  }
  const double m = 1.0 - q;
  switch (kind) {
  case SPH_KERNEL_LUCY:
    *w = norm * (1.0 + 3.0 * q) * m * m * m;
    *dwdr = -12.0 * norm * q * m * m * inv_h;
    return;
  case SPH_KERNEL_CUBIC: {
    const double u = 2.0 * q; /* r / s with s = h/2; d/dr = (2/h) d/du */
    if (u < 1.0) {
      *w = norm * (1.0 - 1.5 * u * u + 0.75 * u * u * u);
      *dwdr = norm * (-3.0 * u + 2.25 * u * u) * 2.0 * inv_h;
    } else {
      const double v = 2.0 - u;
      *w = norm * 0.25 * v * v * v;
      *dwdr = -norm * 0.75 * v * v * 2.0 * inv_h;
    }
    return;
  }
  case SPH_KERNEL_WENDLAND:
    if (dim == 1) {
      *w = norm * (1.0 + 3.0 * q) * m * m * m;
      *dwdr = -12.0 * norm * q * m * m * inv_h;
    } else {
      *w = norm * (1.0 + 4.0 * q) * m * m * m * m;
      *dwdr = -20.0 * norm * q * m * m * m * inv_h;
    }
    return;
  }
}

/* The pair loops' gradient factor (dW/dr)/r, for r < h, with the 1/r taken into the
 * polynomial where the kernel allows (Lucy, Wendland: dW/dr carries a factor q = r/h), so
 * the hot loops do one square root and no division per pair. grad_norm comes from
 * sph_kernel_grad_norm once per sweep; at q = 1 the factor is (-)0. */
SPH_INLINE double sph_kernel_grad_norm(sph_kernel_kind kind, int dim, double norm, double inv_h) {
  switch (kind) {
  case SPH_KERNEL_LUCY:
    return -12.0 * norm * inv_h * inv_h;
  case SPH_KERNEL_CUBIC:
    return norm * 4.0 * inv_h * inv_h;
  case SPH_KERNEL_WENDLAND:
    return dim == 1 ? -12.0 * norm * inv_h * inv_h : -20.0 * norm * inv_h * inv_h;
  }
  return 0.0;
}

/* (dW/dr)/r. For Lucy and Wendland, g (1 - q)^k is evaluated as (g - r g/h) (1 - r/h)^(k-1),
 * each bracket one fused multiply-add (exactly rounded wherever fma runs): three operations
 * instead of four, as the vectorised momentum sweep does them (sph_force_cells.c). */
SPH_INLINE double sph_kernel_grad(sph_kernel_kind kind, int dim, double grad_norm, double norm,
                                  double inv_h, double r) {
  const double q = r * inv_h;
  switch (kind) {
  case SPH_KERNEL_LUCY:
    return fma(-r, grad_norm * inv_h, grad_norm) * fma(-r, inv_h, 1.0);
  case SPH_KERNEL_CUBIC: {
    const double u = 2.0 * q;
    if (u < 1.0)
      return grad_norm * (-3.0 + 2.25 * u); /* (dW/dr)/r = norm (-3 + 9u/4) 4/h^2 */
    const double v = 2.0 - u;               /* the outer piece has no factor u: divide */
    return -norm * 0.75 * v * v * 2.0 * inv_h / r;
  }
  case SPH_KERNEL_WENDLAND: {
    const double gm = fma(-r, grad_norm * inv_h, grad_norm), m = fma(-r, inv_h, 1.0);
    return dim == 1 ? gm * m : gm * m * m;
  }
  }
  return 0.0;
}

#endif
