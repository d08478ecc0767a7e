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
 * the no-slip point on the wall surface. See doc/theory.md.
 *
 * -sph_wall_extrapolation quadratic (walls whose scene gives to_surface = eta n,
 * eta the depth behind the surface, n the unit normal into the liquid): the
 * Shepard mirror is exact for no profile layer by layer (the first wall layer
 * of the channel takes 1.27x the linear continuation, the second 0.33x) and
 * leaves a slip of O(dx^2 v'') that a second-order interior (the kernel
 * correction) no longer hides. Instead each liquid neighbour f, at distance
 * zeta_f = (x_f - x_w).n - eta from the surface, gives the quadratic through
 * the no-slip point, continued to the wall particle:
 *   v_f^w = v_w + (v_w - v_f) eta/zeta_f + beta eta (eta + zeta_f),
 *   beta  = 1/2 d^2 v/d zeta^2 at the surface = (1/(2 nu)) (I - n n)(a_w + grad p/rho0 - g)
 * (the momentum balance at a rigid wall: v = v_w along it, so D v/Dt = a_w and
 * the velocity has no curvature along the surface; the normal part is zero as
 * the pressure extrapolation assumes), with the tangential pressure gradient
 * the W-weighted regression of the liquid's p along the surface, and
 *   v_visc_w = sum_f W_wf v_f^w / sum_f W_wf.
 * Exact for every quadratic profile with no-slip on the surface, on any
 * arrangement of the liquid (zeta_f is kept >= dx/4, so that a particle pressed
 * against the surface cannot make eta/zeta_f explode; the lattice puts the first
 * liquid layer at dx/2). Walls without a surface vector keep Adami's value. */
#include "dmhs/events.h"
#include "sph_kernel.h"
#include "sph_eos.h"
#include "sph_force.h"

struct sph_wall_work {
  PetscInt n_alloc;
  double zeta_min;        /* smallest liquid distance from the surface used (quadratic) [m] */
  double *sum_w;          /* sum_f W_wf */
  double (*sum_v)[2];     /* sum_f v_f W_wf */
  double *sum_p;          /* sum_f p_f W_wf */
  double (*sum_rho_r)[2]; /* sum_f rho_f r_wf W_wf */
  /* quadratic extrapolation only */
  double *sum_w_eta_zeta;      /* sum_f W_wf eta/zeta_f */
  double (*sum_v_eta_zeta)[2]; /* sum_f W_wf v_f eta/zeta_f */
  double *sum_w_zeta;          /* sum_f W_wf zeta_f */
  double (*sum_tau)[3];        /* sum_f W_wf tau_f, tau_f^2, p_f tau_f (tau along the surface) */
  PetscInt64 n_wall_pairs;     /* wall-liquid pairs inside h in the last pass (-log_view flops) */
  /* the wall-liquid pairs of the list (one end a wall: types change only at a build),
   * indices in its order, filtered once per build (wall_filter) */
  PetscInt *sub, n_sub, n_alloc_sub;
  PetscInt64 sub_generation;
};

PetscErrorCode sph_wall_create(sph_wall_work **w) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(w));
  (*w)->sub_generation = -1; /* filtered at the first pass */
  PetscFunctionReturn(0);
}

PetscErrorCode sph_wall_destroy(sph_wall_work **w) {
  PetscFunctionBeginUser;
  if (!*w)
    PetscFunctionReturn(0);
  PetscCall(PetscFree4((*w)->sum_w, (*w)->sum_v, (*w)->sum_p, (*w)->sum_rho_r));
  PetscCall(
      PetscFree4((*w)->sum_w_eta_zeta, (*w)->sum_v_eta_zeta, (*w)->sum_w_zeta, (*w)->sum_tau));
  PetscCall(PetscFree((*w)->sub));
  PetscCall(PetscFree(*w));
  PetscFunctionReturn(0);
}

SPH_INLINE void wall_sums(sph_kernel_kind kernel, int quadratic, sim *s, const sph_params *sp,
                          sph_wall_work *W) {
  const particles *ps = &s->ps;
  const double norm = sph_kernel_norm(kernel, 2, sp->h), inv_h = 1.0 / sp->h;
  const PetscInt *restrict pi = s->cel.pair_i, *restrict pj = s->cel.pair_j;
  for (PetscInt q = 0; q < W->n_sub; q++) {
    const PetscInt k = W->sub[q];
    PetscInt wl = pi[k], f = pj[k];
    if (ps->type[f] == PTYPE_WALL) {
      wl = pj[k];
      f = pi[k];
    }
    const double r_wf[2] = {ps->x[wl][0] - ps->x[f][0], ps->x[wl][1] - ps->x[f][1]};
    const double r2 = r_wf[0] * r_wf[0] + r_wf[1] * r_wf[1];
    if (r2 * inv_h * inv_h >= 1.0)
      continue; /* in the list's skin only */
    W->n_wall_pairs++;
    double w, dwdr;
    sph_kernel_eval(kernel, 2, norm, inv_h, sqrt(r2), &w, &dwdr);
    W->sum_w[wl] += w;
    W->sum_v[wl][0] += ps->v_est[f][0] * w;
    W->sum_v[wl][1] += ps->v_est[f][1] * w;
    W->sum_p[wl] += ps->p[f] * w;
    W->sum_rho_r[wl][0] += ps->rho[f] * r_wf[0] * w;
    W->sum_rho_r[wl][1] += ps->rho[f] * r_wf[1] * w;
    if (quadratic && wl < ps->n_owned) { /* ghost walls take their owner's v_visc */
      const double *sv = ps->to_surface[wl];
      const double eta = sqrt(sv[0] * sv[0] + sv[1] * sv[1]);
      if (eta <= 0.0)
        continue; /* no geometry: Adami's value */
      const double n[2] = {sv[0] / eta, sv[1] / eta};
      const double zeta = PetscMax(-(r_wf[0] * n[0] + r_wf[1] * n[1]) - eta, W->zeta_min);
      const double tau = -(r_wf[0] * -n[1] + r_wf[1] * n[0]); /* (x_f - x_w) . t, t = (-n_y, n_x) */
      const double ez = w * eta / zeta;
      W->sum_w_eta_zeta[wl] += ez;
      W->sum_v_eta_zeta[wl][0] += ez * ps->v_est[f][0];
      W->sum_v_eta_zeta[wl][1] += ez * ps->v_est[f][1];
      W->sum_w_zeta[wl] += w * zeta;
      W->sum_tau[wl][0] += w * tau;
      W->sum_tau[wl][1] += w * tau * tau;
      W->sum_tau[wl][2] += w * tau * ps->p[f];
    }
  }
}

static void wall_sums_lucy(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_LUCY, 0, s, sp, W);
}
static void wall_sums_cubic(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_CUBIC, 0, s, sp, W);
}
static void wall_sums_wendland(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_WENDLAND, 0, s, sp, W);
}
static void wall_sums_lucy_q(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_LUCY, 1, s, sp, W);
}
static void wall_sums_cubic_q(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_CUBIC, 1, s, sp, W);
}
static void wall_sums_wendland_q(sim *s, const sph_params *sp, sph_wall_work *W) {
  wall_sums(SPH_KERNEL_WENDLAND, 1, s, sp, W);
}

/* v_visc of wall i by the quadratic no-slip extrapolation (header comment);
 * false when i has no surface vector */
static PetscBool wall_quadratic_velocity(const particles *ps, const sph_params *sp,
                                         const sph_wall_work *W, PetscInt i, const double g[2],
                                         double v_visc[2]) {
  const double *sv = ps->to_surface[i];
  const double eta = sqrt(sv[0] * sv[0] + sv[1] * sv[1]);
  if (eta <= 0.0)
    return PETSC_FALSE;
  const double n[2] = {sv[0] / eta, sv[1] / eta}, t[2] = {-n[1], n[0]};
  const double sw = W->sum_w[i], inv = 1.0 / sw;
  /* tangential pressure gradient: weighted least squares of p_f against tau_f */
  const double st = W->sum_tau[i][0], stt = W->sum_tau[i][1], spt = W->sum_tau[i][2];
  const double var = stt - st * st * inv;
  const double dpdt = var > 1e-6 * sw * sp->h * sp->h ? (spt - st * W->sum_p[i] * inv) / var : 0.0;
  /* rigid walls at constant velocity: a_w = 0 */
  const double bal[2] = {dpdt * t[0] / sp->rho0 - g[0], dpdt * t[1] / sp->rho0 - g[1]};
  const double bt = sp->nu > 0 ? 0.5 / sp->nu * (bal[0] * t[0] + bal[1] * t[1]) : 0.0;
  const double beta[2] = {bt * t[0], bt * t[1]};
  const double zeta_mean = W->sum_w_zeta[i] * inv;
  for (int k = 0; k < 2; k++)
    v_visc[k] = ps->v[i][k] + (ps->v[i][k] * W->sum_w_eta_zeta[i] - W->sum_v_eta_zeta[i][k]) * inv +
                beta[k] * eta * (eta + zeta_mean);
  return PETSC_TRUE;
}

/* Once per build: the pairs with one wall end (wall-wall pairs are not listed;
 * liquid-liquid ones don't matter here). */
static PetscErrorCode wall_filter(sim *s, sph_wall_work *W) {
  const PetscInt *type = s->ps.type;
  PetscFunctionBeginUser;
  if (s->cel.n_pairs > W->n_alloc_sub) {
    PetscCall(PetscFree(W->sub));
    W->n_alloc_sub = s->cel.n_pairs + s->cel.n_pairs / 4;
    PetscCall(PetscMalloc1(W->n_alloc_sub, &W->sub));
  }
  W->n_sub = 0;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++)
    if ((type[s->cel.pair_i[k]] == PTYPE_WALL) != (type[s->cel.pair_j[k]] == PTYPE_WALL))
      W->sub[W->n_sub++] = k;
  W->sub_generation = s->cel.generation;
  PetscFunctionReturn(0);
}

PetscErrorCode sph_wall_compute(sim *s, const sph_params *sp, const double g[2], sph_wall_work *W) {
  static const char *const refreshed[] = {"v_visc", "p", "rho"};
  static void (*const sums[2][3])(sim *, const sph_params *, sph_wall_work *) = {
      {wall_sums_lucy, wall_sums_cubic, wall_sums_wendland},
      {wall_sums_lucy_q, wall_sums_cubic_q, wall_sums_wendland_q}};
  const int quadratic = sp->wall == SPH_WALL_QUADRATIC;
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_wall, 0, 0, 0, 0));
  if (n > W->n_alloc) {
    PetscCall(PetscFree4(W->sum_w, W->sum_v, W->sum_p, W->sum_rho_r));
    PetscCall(PetscFree4(W->sum_w_eta_zeta, W->sum_v_eta_zeta, W->sum_w_zeta, W->sum_tau));
    W->n_alloc = n + n / 4;
    PetscCall(PetscMalloc4(W->n_alloc, &W->sum_w, W->n_alloc, &W->sum_v, W->n_alloc, &W->sum_p,
                           W->n_alloc, &W->sum_rho_r));
    PetscCall(PetscMalloc4(W->n_alloc, &W->sum_w_eta_zeta, W->n_alloc, &W->sum_v_eta_zeta,
                           W->n_alloc, &W->sum_w_zeta, W->n_alloc, &W->sum_tau));
  }
  if (quadratic) {
    PetscCall(PetscArrayzero(W->sum_w_eta_zeta, n));
    PetscCall(PetscArrayzero(W->sum_v_eta_zeta, n));
    PetscCall(PetscArrayzero(W->sum_w_zeta, n));
    PetscCall(PetscArrayzero(W->sum_tau, n));
    /* a quarter spacing: the first liquid layer sits dx/2 from the surface at
     * rest, and a floor at exactly that distance bit whenever the layer was
     * compressed by a hair (the quick channel then slipped by 7.7e-6 v_ref at
     * t = 4 s instead of 2.8e-7) */
    W->zeta_min = 0.25 * (s->dx > 0 ? s->dx : sp->h / 3.0);
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
  if (W->sub_generation != s->cel.generation)
    PetscCall(wall_filter(s, W));
  W->n_wall_pairs = 0;
  sums[quadratic][sp->kernel](s, sp, W);
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_WALL)
      continue;
    if (W->sum_w[i] <= 0.0) {
      ps->rho[i] = sp->rho0;
      ps->p[i] = sph_eos_pressure_bg(sp, sp->rho0);
      continue;
    }
    const double inv = 1.0 / W->sum_w[i];
    if (!quadratic || !wall_quadratic_velocity(ps, sp, W, i, g, ps->v_visc[i])) {
      ps->v_visc[i][0] = 2.0 * ps->v[i][0] - W->sum_v[i][0] * inv;
      ps->v_visc[i][1] = 2.0 * ps->v[i][1] - W->sum_v[i][1] * inv;
    }
    ps->p[i] = (W->sum_p[i] + g[0] * W->sum_rho_r[i][0] + g[1] * W->sum_rho_r[i][1]) * inv;
    ps->rho[i] = sph_eos_density_bg(sp, ps->p[i]);
  }
  /* the kernel and the nine sums of a wall-liquid pair (the quadratic extrapolation's extra
   * sums not counted); the other pairs of the list cost a type test each */
  PetscCall(PetscLogFlops(30.0 * (double)W->n_wall_pairs));
  PetscCall(PetscLogEventEnd(events.sph_wall, 0, 0, 0, 0));
  PetscCall(halo_forward(&s->hal, ps, refreshed, 3));
  PetscFunctionReturn(0);
}
