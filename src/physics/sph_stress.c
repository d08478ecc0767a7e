/* SPH contributions to the per-particle stress diagnostics (src/diag/stress.c),
 * from the state of the last force evaluation (p, rho, v_visc as the momentum
 * sweep used them), with the same pair arithmetic (sph_force_iact.h):
 *   virial   W_i += -1/2 r_ij (x) F_ij,  F_ij = m_i m_j T_ij (pressure + Morris
 *            viscosity [+ artificial viscosity]), to both particles of a pair;
 *   pressure force  F_p,i = -m_i sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij
 *            (its magnitude, into the optional field pressure_force);
 *   velocity gradient  L_i = sum_j (m_j/rho_j) (v_j - v_i) (x) grad_i W_ij with
 *            the viscous velocities (walls: the extrapolated no-slip values), and
 *            the shear rate sqrt(2 D:D), D = (L + L^T)/2 (optional field shear_rate).
 * Runs at output times only: one plain loop, no specialised sweeps. */
#include "dmhs/sim.h"
#include "sph_force_iact.h"
#include "sph_force.h"

PetscErrorCode sph_stress_virial(sim *s, const sph_params *sp, const double (*vv)[2],
                                 double (*W)[3]) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  const double h2 = sp->h * sp->h, inv_h = 1.0 / sp->h,
               norm = sph_kernel_norm(sp->kernel, 2, sp->h),
               grad_norm = sph_kernel_grad_norm(sp->kernel, 2, norm, inv_h);
  const double sqrt_mu_sum = sqrt(2.0 * sp->rho0 * sp->nu); /* sph_force_iact's J = this / rho */
  const int artificial = sp->av_alpha > 0.0 || sp->av_beta > 0.0;
  double(*fp)[2], (*L)[4];
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc2(n, &fp, n, &L));
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = s->cel.pair_i[k], j = s->cel.pair_j[k];
    const double rij[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double r2 = PetscMax(rij[0] * rij[0] + rij[1] * rij[1], SPH_R2_FLOOR * h2);
    if (r2 >= h2)
      continue;
    const double r = sqrt(r2);
    const double grad = sph_kernel_grad(sp->kernel, 2, grad_norm, norm, inv_h, r);
    const double inv_ri = 1.0 / ps->rho[i], inv_rj = 1.0 / ps->rho[j];
    const double Pi = ps->p[i] * inv_ri * inv_ri, Pj = ps->p[j] * inv_rj * inv_rj;
    const double vvisc[2] = {vv[i][0] - vv[j][0], vv[i][1] - vv[j][1]};
    double T[2], Tp[2];
    sph_force_iact(rij, grad, Pi, Pj, sqrt_mu_sum * inv_ri, sqrt_mu_sum * inv_rj, vvisc, T);
    if (artificial) {
      const double vij[2] = {ps->v_est[i][0] - ps->v_est[j][0], ps->v_est[i][1] - ps->v_est[j][1]};
      sph_force_iact_artificial_viscosity(rij, r2, grad, ps->rho[i], ps->rho[j], vij, sp->av_alpha,
                                          sp->av_beta, sp->c0, sp->h, T);
    }
    const double zero[2] = {0, 0};
    sph_force_iact(rij, grad, Pi, Pj, 0.0, 0.0, zero, Tp); /* pressure part only */
    const double mm = ps->mass[i] * ps->mass[j];
    const double wv[3] = {-0.5 * mm * rij[0] * T[0], -0.5 * mm * rij[0] * T[1],
                          -0.5 * mm * rij[1] * T[1]};
    for (int c = 0; c < 3; c++) {
      W[i][c] += wv[c];
      W[j][c] += wv[c];
    }
    for (int c = 0; c < 2; c++) {
      fp[i][c] += mm * Tp[c];
      fp[j][c] -= mm * Tp[c];
    }
    /* grad_i W_ij = grad r_ij; (v_j - v_i) = -vvisc */
    const double g[2] = {grad * rij[0], grad * rij[1]};
    const double vi = ps->mass[j] * inv_rj, vj = ps->mass[i] * inv_ri;
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2; b++) {
        L[i][2 * a + b] -= vi * vvisc[a] * g[b];
        L[j][2 * a + b] -= vj * vvisc[a] * g[b];
      }
  }
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->pressure_force)
      ps->pressure_force[i] = hypot(fp[i][0], fp[i][1]);
    if (ps->shear_rate) {
      const double dxx = L[i][0], dyy = L[i][3], dxy = 0.5 * (L[i][1] + L[i][2]);
      ps->shear_rate[i] = sqrt(2.0 * (dxx * dxx + dyy * dyy + 2.0 * dxy * dxy));
    }
  }
  PetscCall(PetscFree2(fp, L));
  PetscFunctionReturn(0);
}
