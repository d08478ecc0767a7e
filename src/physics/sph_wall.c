/* Wall boundary values (Adami, Hu & Adams 2012, J. Comput. Phys. 231:7057).
 *
 * A wall particle w takes the values the liquid would have there, from the
 * kernel-weighted (Shepard) average over the liquid particles f around it:
 *   v~_w     = sum_f v_f W_wf / sum_f W_wf
 *   v_visc_w = 2 v_w - v~_w              (the velocity the viscous term sees:
 *                                          the profile continues antisymmetrically
 *                                          through the wall, so v = v_w exactly on it)
 *   p_w      = [sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf] / sum_f W_wf
 *   rho_w    = EOS^-1(p_w - p_b)       (p_b: background pressure, sph_eos.h)
 * with r_wf = x_w - x_f, g the body acceleration on the liquid and a_w = 0
 * (walls move at constant prescribed velocity). A wall particle with no
 * liquid within the support keeps v_visc = v_w, rho = rho0 and p = EOS(rho0).
 *
 * Why this and not walls that just carry their velocity: those slip by about
 * 0.6 dx (the bar LAMMPS sets on the channel cases); the extrapolation puts
 * the no-slip point on the wall surface. See doc/theory.md. */
#include "dmhs/events.h"
#include "sph_kernel.h"
#include "sph_eos.h"
#include "sph_force.h"

struct sph_wall_work {
  PetscInt n_alloc;
  double *sum_w;         /* sum_f W_wf */
  double (*sum_v)[2];    /* sum_f v_f W_wf */
  double *sum_p;         /* sum_f p_f W_wf */
  double (*sum_rho_r)[2]; /* sum_f rho_f r_wf W_wf */
};

PetscErrorCode sph_wall_create(sph_wall_work **w) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(w));
  PetscFunctionReturn(0);
}

PetscErrorCode sph_wall_destroy(sph_wall_work **w) {
  PetscFunctionBeginUser;
  if (!*w) PetscFunctionReturn(0);
  PetscCall(PetscFree4((*w)->sum_w, (*w)->sum_v, (*w)->sum_p, (*w)->sum_rho_r));
  PetscCall(PetscFree(*w));
  PetscFunctionReturn(0);
}

SPH_INLINE void wall_sums(sph_kernel_kind kernel, sim *s, sph_wall_work *W) {
  const particles *ps = &s->ps;
  const double norm = sph_kernel_norm(kernel, 2, s->sph.h), inv_h = 1.0 / s->sph.h;
  const PetscInt *restrict pi = s->cel.pair_i, *restrict pj = s->cel.pair_j;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    PetscInt wl = pi[k], f = pj[k];
    const int wi = ps->type[wl] == PTYPE_WALL, wj = ps->type[f] == PTYPE_WALL;
    if (wi == wj) continue; /* wall-wall pairs are not listed; liquid-liquid ones don't matter here */
    if (wj) {
      wl = pj[k];
      f = pi[k];
    }
    const double r_wf[2] = {ps->x[wl][0] - ps->x[f][0], ps->x[wl][1] - ps->x[f][1]};
    const double r2 = r_wf[0] * r_wf[0] + r_wf[1] * r_wf[1];
    if (r2 * inv_h * inv_h >= 1.0) continue; /* in the list's skin only */
    double w, dwdr;
    sph_kernel_eval(kernel, 2, norm, inv_h, sqrt(r2), &w, &dwdr);
    W->sum_w[wl] += w;
    W->sum_v[wl][0] += ps->v_est[f][0] * w;
    W->sum_v[wl][1] += ps->v_est[f][1] * w;
    W->sum_p[wl] += ps->p[f] * w;
    W->sum_rho_r[wl][0] += ps->rho[f] * r_wf[0] * w;
    W->sum_rho_r[wl][1] += ps->rho[f] * r_wf[1] * w;
  }
}

static void wall_sums_lucy(sim *s, sph_wall_work *W) { wall_sums(SPH_KERNEL_LUCY, s, W); }
static void wall_sums_cubic(sim *s, sph_wall_work *W) { wall_sums(SPH_KERNEL_CUBIC, s, W); }
static void wall_sums_wendland(sim *s, sph_wall_work *W) { wall_sums(SPH_KERNEL_WENDLAND, s, W); }

PetscErrorCode sph_wall_compute(sim *s, sph_wall_work *W) {
  static const char *const refreshed[] = {"v_visc", "p", "rho"};
  static void (*const sums[])(sim *, sph_wall_work *) = {wall_sums_lucy, wall_sums_cubic,
                                                          wall_sums_wendland};
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_wall, 0, 0, 0, 0));
  if (n > W->n_alloc) {
    PetscCall(PetscFree4(W->sum_w, W->sum_v, W->sum_p, W->sum_rho_r));
    W->n_alloc = n + n / 4;
    PetscCall(PetscMalloc4(W->n_alloc, &W->sum_w, W->n_alloc, &W->sum_v, W->n_alloc, &W->sum_p,
                           W->n_alloc, &W->sum_rho_r));
  }
  PetscCall(PetscArrayzero(W->sum_w, n));
  PetscCall(PetscArrayzero(W->sum_v, n));
  PetscCall(PetscArrayzero(W->sum_p, n));
  PetscCall(PetscArrayzero(W->sum_rho_r, n));
  /* moving particles see their own predicted velocity in the viscous term */
  for (PetscInt i = 0; i < n; i++) {
    ps->v_visc[i][0] = ps->v_est[i][0];
    ps->v_visc[i][1] = ps->v_est[i][1];
  }
  sums[s->sph.kernel](s, W);
  const double g[2] = {s->body_accel[0], s->body_accel[1]};
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_WALL) continue;
    if (W->sum_w[i] <= 0.0) {
      ps->rho[i] = s->sph.rho0;
      ps->p[i] = sph_eos_pressure_bg(&s->sph, s->sph.rho0);
      continue;
    }
    const double inv = 1.0 / W->sum_w[i];
    ps->v_visc[i][0] = 2.0 * ps->v[i][0] - W->sum_v[i][0] * inv;
    ps->v_visc[i][1] = 2.0 * ps->v[i][1] - W->sum_v[i][1] * inv;
    ps->p[i] = (W->sum_p[i] + g[0] * W->sum_rho_r[i][0] + g[1] * W->sum_rho_r[i][1]) * inv;
    ps->rho[i] = sph_eos_density_bg(&s->sph, ps->p[i]);
  }
  PetscCall(PetscLogFlops(30.0 * (double)s->cel.n_pairs));
  PetscCall(PetscLogEventEnd(events.sph_wall, 0, 0, 0, 0));
  PetscCall(halo_forward(&s->hal, ps, refreshed, 3));
  PetscFunctionReturn(0);
}
