/* Equations of state, per particle (computed once per particle, never per pair).
 *   Tait:            p = B [ (rho/rho0)^7 - 1 ],  B = c0^2 rho0 / 7
 *   linear:          p = c0^2 rho            ("artificial compressibility")
 *   linear shifted:  p = c0^2 (rho - rho0)
 * and their inverses (rho from p), used to give wall particles the density
 * that matches their extrapolated pressure.
 *
 * Background pressure (-sph_p_background p_b, default 0): the solver uses
 *   p = EOS(rho) + p_b,   rho = EOS^-1(p - p_b)      (sph_eos_pressure_bg / _density_bg)
 * A constant p_b changes no force in the continuum (only grad p enters), but
 * in the SPH sum it keeps p > 0 where the flow pulls the liquid into tension
 * (behind an obstacle), which suppresses the tensile instability and the
 * particle-free voids it opens; with Tait it also lifts the tension floor
 * -B (no density exists below it) to p_b - B. Choose p_b above the largest
 * expected dynamic/viscous pressure drop; it stiffens nothing (the sound
 * speed, hence the time step, is unchanged). */
#ifndef DMHS_SPH_EOS_H
#define DMHS_SPH_EOS_H
#include <math.h>
#include "dmhs/sph.h"

static inline double sph_eos_pressure(sph_eos_kind kind, double rho, double rho0, double c0) {
  switch (kind) {
  case SPH_EOS_TAIT: {
    const double r = rho / rho0, r2 = r * r, r4 = r2 * r2;
    return c0 * c0 * rho0 / 7.0 * (r4 * r2 * r - 1.0);
  }
  case SPH_EOS_LINEAR:
    return c0 * c0 * rho;
  case SPH_EOS_LINEAR_SHIFTED:
    return c0 * c0 * (rho - rho0);
  }
  return 0.0;
}

/* Inverse of sph_eos_pressure. Tait tension below -B has no density: clamp to
 * a tiny positive density rather than produce NaN. */
static inline double sph_eos_density(sph_eos_kind kind, double p, double rho0, double c0) {
  switch (kind) {
  case SPH_EOS_TAIT: {
    const double base = 1.0 + 7.0 * p / (c0 * c0 * rho0);
    return rho0 * pow(base > 1e-12 ? base : 1e-12, 1.0 / 7.0);
  }
  case SPH_EOS_LINEAR:
    return p / (c0 * c0);
  case SPH_EOS_LINEAR_SHIFTED:
    return rho0 + p / (c0 * c0);
  }
  return rho0;
}

/* The EOS as the solver uses it: with the background pressure p_b of sp. */
static inline double sph_eos_pressure_bg(const sph_params *sp, double rho) {
  return sph_eos_pressure(sp->eos, rho, sp->rho0, sp->c0) + sp->p_background;
}

static inline double sph_eos_density_bg(const sph_params *sp, double p) {
  return sph_eos_density(sp->eos, p - sp->p_background, sp->rho0, sp->c0);
}

#endif
