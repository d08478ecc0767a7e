/* SPH momentum and continuity pair terms (src/physics/sph_force_iact.h) and the
 * whole force sweep (sph_force_compute). Proves:
 *   - swapping i and j (r_ij -> -r_ij, v_ij -> -v_ij, rho and p swapped) negates
 *     the momentum pair term T exactly (bit for bit), with and without artificial viscosity, so
 *     m_i a_i + m_j a_j = 0, and leaves the continuity scalar unchanged;
 *   - pressure pushes a pair apart;
 *   - on a random cloud in a periodic box (ghosts + pair list), for every kernel,
 *     with and without artificial viscosity and continuity: each owned particle's
 *     acceleration (and d rho/dt) equals a brute-force minimum-image sum over all
 *     other particles, and the total momentum change sum m_i a_i is zero to
 *     round-off (1e-12 of sum |m_i a_i|);
 *   - summation density on the same clouds equals the brute-force sum (self term
 *     included) and ghosts carry their source's density;
 *   - with -sph_kernel_correction (sph_correction.c + the corrected sweeps), each
 *     owned particle's acceleration and d rho/dt equal a brute-force evaluation
 *     of the corrected operators (sph_correction_iact.h) over all other particles,
 *     with and without artificial viscosity, for every kernel;
 *   - Monaghan's artificial pressure (sph_tensile_iact.h, sph_tensile.c): its pair term is
 *     antisymmetric bit for bit and repulsive, zero without tension, eps |P| grad r_ij at
 *     r = dx; the pass equals a brute-force sum, conserves momentum and leaves a liquid at
 *     positive pressure untouched. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "physics/sph_force.h"
#include "physics/sph_force_iact.h"
#include "physics/sph_eos.h"
#include "physics/sph_correction_iact.h"
#include "physics/sph_tensile_iact.h"

static const double h = 0.1, rho0 = 1000.0, c0 = 10.0, nu = 1e-3;
/* the liquid's parameters (the sph module's, passed to its passes as it does) */
static sph_params sph_p;

typedef struct {
  double rij[2], r, dwdr, rho_i, rho_j, p_i, p_j, v_i[2], v_j[2];
} pair_state;

static pair_state random_pair(unit_rng *g, sph_kernel_kind kernel) {
  pair_state P;
  const double r = unit_range(g, 0.02 * h, 0.98 * h), phi = unit_range(g, 0.0, 2.0 * M_PI);
  P.rij[0] = r * cos(phi);
  P.rij[1] = r * sin(phi);
  P.r = r;
  double w = 0;
  sph_kernel_eval(kernel, 2, sph_kernel_norm(kernel, 2, h), 1.0 / h, r, &w, &P.dwdr);
  P.rho_i = unit_range(g, 0.97, 1.03) * rho0;
  P.rho_j = unit_range(g, 0.97, 1.03) * rho0;
  P.p_i = sph_eos_pressure(SPH_EOS_TAIT, P.rho_i, rho0, c0);
  P.p_j = sph_eos_pressure(SPH_EOS_TAIT, P.rho_j, rho0, c0);
  for (int k = 0; k < 2; k++) {
    P.v_i[k] = unit_range(g, -1.0, 1.0);
    P.v_j[k] = unit_range(g, -1.0, 1.0);
  }
  return P;
}

/* T for the pair seen from i (sign +1) or from j (sign -1, everything swapped). */
static void pair_term(const pair_state *P, int from_j, double alpha, double beta, double T[2]) {
  const double s = from_j ? -1.0 : 1.0;
  const double rij[2] = {s * P->rij[0], s * P->rij[1]};
  const double vij[2] = {s * (P->v_i[0] - P->v_j[0]), s * (P->v_i[1] - P->v_j[1])};
  const double rho_a = from_j ? P->rho_j : P->rho_i, rho_b = from_j ? P->rho_i : P->rho_j;
  const double p_a = from_j ? P->p_j : P->p_i, p_b = from_j ? P->p_i : P->p_j;
  const double grad = P->dwdr / P->r, r2 = P->r * P->r;
  const double sqrt_mu_sum = sqrt(2.0 * rho0 * nu);
  sph_force_iact(rij, grad, p_a / (rho_a * rho_a), p_b / (rho_b * rho_b), sqrt_mu_sum / rho_a,
                 sqrt_mu_sum / rho_b, vij, T);
  sph_force_iact_artificial_viscosity(rij, r2, grad, rho_a, rho_b, vij, alpha, beta, c0, h, T);
}

static void test_pair_antisymmetry(void **state) {
  (void)state;
  unit_rng g = {42};
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  int approaching = 0;
  for (int trial = 0; trial < 3000; trial++) {
    const pair_state P = random_pair(&g, kernels[trial % 3]);
    const double alpha = (trial / 3) % 2 ? 0.1 : 0.0, beta = (trial / 3) % 2 ? 0.2 : 0.0;
    double Tij[2], Tji[2];
    pair_term(&P, 0, alpha, beta, Tij);
    pair_term(&P, 1, alpha, beta, Tji);
    const double mag = hypot(Tij[0], Tij[1]);
    assert_true(mag > 0.0);
    /* exactly, bit for bit: the runs on 1..N ranks list a pair in either order
     * and stay bitwise identical only if the swap is exact (doc/parallel.md) */
    assert_true(Tji[0] == -Tij[0]);
    assert_true(Tji[1] == -Tij[1]);
    /* m_i a_i + m_j a_j = m_i m_j (T_ij + T_ji) = 0 */
    const double vij[2] = {P.v_i[0] - P.v_j[0], P.v_i[1] - P.v_j[1]};
    const double vji[2] = {-vij[0], -vij[1]}, rji[2] = {-P.rij[0], -P.rij[1]};
    const double q_ij = sph_continuity_iact(P.rij, P.dwdr / P.r, vij);
    const double q_ji = sph_continuity_iact(rji, P.dwdr / P.r, vji);
    assert_true(q_ji == q_ij);
    approaching += vij[0] * P.rij[0] + vij[1] * P.rij[1] < 0;
  }
  assert_true(approaching > 500); /* the artificial viscosity branch ran */
}

static void test_artificial_viscosity_only_when_approaching(void **state) {
  (void)state;
  unit_rng g = {7};
  for (int trial = 0; trial < 200; trial++) {
    const pair_state P = random_pair(&g, SPH_KERNEL_WENDLAND);
    double T0[2], T1[2];
    pair_term(&P, 0, 0.0, 0.0, T0);
    pair_term(&P, 0, 1.0, 2.0, T1);
    const double vr = (P.v_i[0] - P.v_j[0]) * P.rij[0] + (P.v_i[1] - P.v_j[1]) * P.rij[1];
    if (vr >= 0)
      assert_true(T0[0] == T1[0] && T0[1] == T1[1]);
    /* approaching pairs are pushed apart harder */
    else
      assert_true((T1[0] - T0[0]) * P.rij[0] + (T1[1] - T0[1]) * P.rij[1] > 0.0);
  }
}

static void test_pressure_repels(void **state) {
  (void)state;
  unit_rng g = {3};
  for (int trial = 0; trial < 100; trial++) {
    pair_state P = random_pair(&g, SPH_KERNEL_CUBIC);
    P.p_i = fabs(P.p_i) + 1.0;
    P.p_j = fabs(P.p_j) + 1.0;
    P.v_i[0] = P.v_j[0];
    P.v_i[1] = P.v_j[1];
    double T[2];
    pair_term(&P, 0, 0.0, 0.0, T);
    assert_true(T[0] * P.rij[0] + T[1] * P.rij[1] > 0.0);
  }
}

/* ---- whole sweep ---- */

/* When set, the second particle of a cloud sits exactly on the first (a pair
 * that clumped: r = 0). */
static int cloud_coincident = 0;

/* A random cloud of n fluid particles in a periodic [0, Lx) x [0, Ly) box, with
 * ghosts and the pair list built as neighbours_rebuild does. */
/* every 7th particle a wall (the wall-wall pairs the pair list leaves out) */
static int cloud_walls = 0;
/* 1: the owned rows sorted into cell order first, as neighbours_rebuild does (long runs of
 * consecutive rows in the cell order); 2: that, with x closed (no ghosts at the ends of a row of
 * cells, so those runs go on from one row of cells into the next) */
static int cloud_layout = 0;

static void build_cloud(sim *s, PetscInt n, sph_kernel_kind kernel, double alpha,
                        sph_density_kind density, unit_rng *g) {
  OK(PetscMemzero(s, sizeof(*s)));
  s->comm = PETSC_COMM_SELF;
  sph_p = (sph_params){.kernel = kernel,
                       .h = h,
                       .rho0 = rho0,
                       .c0 = c0,
                       .nu = nu,
                       .eos = SPH_EOS_TAIT,
                       .density = density,
                       .av_alpha = alpha,
                       .av_beta = 2.0 * alpha};
  s->dom =
      (domain){.lo = {0.0, 0.0}, .hi = {0.5, 0.35}, .periodic = {cloud_layout < 2, PETSC_TRUE}};
  s->pair_cutoff = h;
  fields_reset();
  OK(fields_enable("v_visc")); /* the sweeps' viscous velocity, as with walls */
  OK(unit_enable_sph_fields());
  OK(particles_create(&s->ps));
  for (PetscInt i = 0; i < n; i++) {
    double x[2] = {unit_range(g, 0.0, 0.5), unit_range(g, 0.0, 0.35)};
    const double v[2] = {unit_range(g, -1.0, 1.0), unit_range(g, -1.0, 1.0)};
    if (cloud_coincident && i == 1) {
      x[0] = s->ps.x[0][0];
      x[1] = s->ps.x[0][1];
    }
    const double rho = unit_range(g, 0.98, 1.02) * rho0;
    PetscInt idx;
    const double m = unit_range(g, 0.5, 1.5);
    const particle_type type = cloud_walls && i % 7 == 3 ? PTYPE_WALL : PTYPE_FLUID;
    OK(particles_add_owned(&s->ps, 1000 + i, type, x, v, m, rho, &idx));
    s->ps.p[idx] = sph_eos_pressure(SPH_EOS_TAIT, rho, rho0, c0);
    s->ps.v_est[idx][0] = v[0] + unit_range(g, -0.1, 0.1); /* distinct from v_visc */
    s->ps.v_est[idx][1] = v[1] + unit_range(g, -0.1, 0.1);
  }
  const double lo[2] = {-h, -h}, hi[2] = {0.5 + h, 0.35 + h};
  if (cloud_layout)
    OK(cells_sort_owned_rows(&s->ps, lo, hi, h));
  OK(halo_create(&s->hal, h, PETSC_COMM_SELF));
  OK(halo_build(&s->hal, &s->dom, NULL, &s->ps)); /* one rank: no partition needed */
  OK(cells_create(&s->cel));
  OK(cells_build_pairs(&s->cel, &s->ps, lo, hi, h));
  const PetscInt rows = s->ps.n_owned + s->ps.n_ghost;
  OK(PetscArrayzero(s->ps.a, rows));
  OK(PetscArrayzero(s->ps.drho, rows));
}

static void destroy_cloud(sim *s) {
  OK(cells_destroy(&s->cel));
  OK(halo_destroy(&s->hal));
  OK(particles_destroy(&s->ps));
}

/* Acceleration and density rate of owned particle i by direct summation over all
 * other owned particles with the minimum-image separation. */
static void brute_force(const sim *s, PetscInt i, double a[2], double *drho) {
  const particles *ps = &s->ps;
  const sph_params *sp = &sph_p;
  const double norm = sph_kernel_norm(sp->kernel, 2, h);
  a[0] = a[1] = *drho = 0.0;
  for (PetscInt j = 0; j < ps->n_owned; j++) {
    if (j == i)
      continue;
    double rij[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    domain_min_image(&s->dom, rij);
    const double r = hypot(rij[0], rij[1]);
    if (r >= h)
      continue;
    double w = 0, dwdr = 0, T[2];
    sph_kernel_eval(sp->kernel, 2, norm, 1.0 / h, r, &w, &dwdr);
    const double vv[2] = {ps->v_visc[i][0] - ps->v_visc[j][0], ps->v_visc[i][1] - ps->v_visc[j][1]};
    const double ve[2] = {ps->v_est[i][0] - ps->v_est[j][0], ps->v_est[i][1] - ps->v_est[j][1]};
    /* Morris (1997) written out here, independently of sph_force_iact */
    const double grad = dwdr / r;
    const double press =
        -(ps->p[i] / (ps->rho[i] * ps->rho[i]) + ps->p[j] / (ps->rho[j] * ps->rho[j]));
    const double visc = 2.0 * rho0 * nu / (ps->rho[i] * ps->rho[j]) * grad;
    for (int d = 0; d < 2; d++)
      T[d] = press * grad * rij[d] + visc * vv[d];
    if (sp->av_alpha > 0)
      sph_force_iact_artificial_viscosity(rij, r * r, grad, ps->rho[i], ps->rho[j], ve,
                                          sp->av_alpha, sp->av_beta, c0, h, T);
    a[0] += ps->mass[j] * T[0];
    a[1] += ps->mass[j] * T[1];
    *drho += ps->mass[j] * sph_continuity_iact(rij, grad, ve);
  }
}

static void test_sweep_conserves_momentum(void **state) {
  (void)state;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  unit_rng g = {2024};
  static sim s;
  static sph_force_work work;
  for (int k = 0; k < 3; k++)
    for (int av = 0; av < 2; av++)
      for (int cont = 0; cont < 2; cont++) {
        const sph_density_kind density = cont ? SPH_DENSITY_CONTINUITY : SPH_DENSITY_SUMMATION;
        build_cloud(&s, 150, kernels[k], av ? 0.5 : 0.0, density, &g);
        assert_true(s.ps.n_ghost > 0 && s.cel.n_pairs > 150);
        OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
        double P[2] = {0, 0}, scale = 0, amax = 0, dmax = 0;
        for (PetscInt i = 0; i < s.ps.n_owned; i++)
          for (int d = 0; d < 2; d++) {
            P[d] += s.ps.mass[i] * s.ps.a[i][d];
            scale += fabs(s.ps.mass[i] * s.ps.a[i][d]);
            amax = fmax(amax, fabs(s.ps.a[i][d]));
          }
        for (PetscInt i = 0; i < s.ps.n_owned; i++)
          dmax = fmax(dmax, fabs(s.ps.drho[i]));
        assert_true(scale > 0);
        if (fabs(P[0]) > 1e-12 * scale || fabs(P[1]) > 1e-12 * scale)
          fail_msg("kernel %d av %d continuity %d: sum m a = (%g, %g), sum |m a| = %g", k, av, cont,
                   P[0], P[1], scale);
        for (PetscInt i = 0; i < s.ps.n_owned; i++) {
          double a[2], drho;
          brute_force(&s, i, a, &drho);
          assert_close(s.ps.a[i][0], a[0], 1e-12 * amax);
          assert_close(s.ps.a[i][1], a[1], 1e-12 * amax);
          if (cont)
            assert_close(s.ps.drho[i], drho, 1e-12 * dmax);
          else
            assert_true(s.ps.drho[i] == 0.0);
        }
        destroy_cloud(&s);
      }
}

/* Two particles on top of each other (r = 0, where dW/dr / r is finite but
 * computes as 0/0): every acceleration and density rate stays finite, with
 * density diffusion too, momentum is conserved, and the pair's viscous
 * coupling is the r -> 0 limit of the Morris term, -12 norm/h^2 (Lucy) times
 * mu_sum/(rho_i rho_j) v_ij. */
static void test_coincident_pair(void **state) {
  (void)state;
  unit_rng g = {77};
  static sim s;
  static sph_force_work work;
  cloud_coincident = 1;
  build_cloud(&s, 60, SPH_KERNEL_LUCY, 0.0, SPH_DENSITY_CONTINUITY, &g);
  cloud_coincident = 0;
  sph_p.delta = 0.1;
  assert_true(s.ps.x[0][0] == s.ps.x[1][0] && s.ps.x[0][1] == s.ps.x[1][1]);
  OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
  double P[2] = {0, 0}, scale = 0;
  for (PetscInt i = 0; i < s.ps.n_owned; i++) {
    assert_true(isfinite(s.ps.a[i][0]) && isfinite(s.ps.a[i][1]) && isfinite(s.ps.drho[i]));
    for (int d = 0; d < 2; d++) {
      P[d] += s.ps.mass[i] * s.ps.a[i][d];
      scale += fabs(s.ps.mass[i] * s.ps.a[i][d]);
    }
  }
  assert_true(fabs(P[0]) <= 1e-12 * scale && fabs(P[1]) <= 1e-12 * scale);
  /* particle 0 against the same sum without its twin, plus the limit term */
  double a_all[2], drho;
  sph_p.delta = 0.0;
  OK(PetscArrayzero(s.ps.a, s.ps.n_owned + s.ps.n_ghost));
  OK(PetscArrayzero(s.ps.drho, s.ps.n_owned + s.ps.n_ghost));
  OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
  a_all[0] = s.ps.a[0][0];
  a_all[1] = s.ps.a[0][1];
  const double mass1 = s.ps.mass[1];
  s.ps.mass[1] = 0.0; /* the twin's contributions to particle 0 vanish */
  OK(PetscArrayzero(s.ps.a, s.ps.n_owned + s.ps.n_ghost));
  OK(PetscArrayzero(s.ps.drho, s.ps.n_owned + s.ps.n_ghost));
  OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
  (void)drho;
  const double F0 = -12.0 * sph_kernel_norm(SPH_KERNEL_LUCY, 2, h) / (h * h);
  const double mu_sum = 2.0 * rho0 * nu;
  for (int d = 0; d < 2; d++) {
    const double vv = s.ps.v_visc[0][d] - s.ps.v_visc[1][d];
    const double twin = mass1 * mu_sum / (s.ps.rho[0] * s.ps.rho[1]) * F0 * vv;
    assert_close(a_all[d], s.ps.a[0][d] + twin, 1e-9 * (fabs(a_all[d]) + fabs(twin)));
  }
  destroy_cloud(&s);
}

/* Summation density over the same clouds: rho_i = sum_j m_j W_ij (self included)
 * for owned rows, and each ghost row takes its source's value. */
static void test_summation_density(void **state) {
  (void)state;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  unit_rng g = {77};
  static sim s;
  for (int k = 0; k < 3; k++) {
    build_cloud(&s, 150, kernels[k], 0.0, SPH_DENSITY_SUMMATION, &g);
    OK(sph_density_summation(&s, &sph_p));
    const particles *ps = &s.ps;
    const double norm = sph_kernel_norm(kernels[k], 2, h);
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      double sum = ps->mass[i] * norm; /* W(0) = norm for all three kernels */
      for (PetscInt j = 0; j < ps->n_owned; j++) {
        if (j == i)
          continue;
        double rij[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]}, w = 0, dwdr = 0;
        domain_min_image(&s.dom, rij);
        sph_kernel_eval(kernels[k], 2, norm, 1.0 / h, hypot(rij[0], rij[1]), &w, &dwdr);
        sum += ps->mass[j] * w;
      }
      assert_close(ps->rho[i], sum, 1e-12 * sum);
    }
    for (PetscInt gh = 0; gh < ps->n_ghost; gh++)
      assert_true(ps->rho[ps->n_owned + gh] == ps->rho[s.hal.source[gh]]);
    destroy_cloud(&s);
  }
}

/* Owned neighbours of i within h (minimum image): separation, kernel slope. */
typedef struct {
  PetscInt j;
  double rij[2], r, dwdr, F, inv_r2;
} nb_entry;

static int neighbours_of(const sim *s, PetscInt i, nb_entry *nb, int max) {
  const particles *ps = &s->ps;
  const double norm = sph_kernel_norm(sph_p.kernel, 2, h);
  int n = 0;
  for (PetscInt j = 0; j < ps->n_owned; j++) {
    if (j == i)
      continue;
    nb_entry e = {.j = j, .rij = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]}};
    domain_min_image(&s->dom, e.rij);
    e.r = hypot(e.rij[0], e.rij[1]);
    if (e.r >= h)
      continue;
    double w = 0;
    sph_kernel_eval(sph_p.kernel, 2, norm, 1.0 / h, e.r, &w, &e.dwdr);
    const double r2 = e.rij[0] * e.rij[0] + e.rij[1] * e.rij[1];
    e.inv_r2 = 1.0 / r2;
    e.F = e.dwdr * (sqrt(r2) * e.inv_r2);
    assert_true(n < max);
    nb[n++] = e;
  }
  return n;
}

/* The corrected operators of owned particle i by direct summation. */
static void brute_force_corrected(const sim *s, PetscInt i, double a[2], double *drho) {
  const particles *ps = &s->ps;
  const sph_params *sp = &sph_p;
  static nb_entry nb[256];
  const int n = neighbours_of(s, i, nb, 256);
  sph_moments m = {0};
  for (int k = 0; k < n; k++) {
    const PetscInt j = nb[k].j;
    const double vji[2] = {ps->v_visc[j][0] - ps->v_visc[i][0],
                           ps->v_visc[j][1] - ps->v_visc[i][1]};
    sph_moments_pair(nb[k].rij, nb[k].F, nb[k].inv_r2, vji, ps->mass[j] / ps->rho[j], &m);
  }
  sph_correction c;
  sph_correction_from_moments(&m, &c);
  a[0] = a[1] = 0.0;
  for (int k = 0; k < n; k++) {
    const PetscInt j = nb[k].j;
    const double vv[2] = {ps->v_visc[i][0] - ps->v_visc[j][0], ps->v_visc[i][1] - ps->v_visc[j][1]};
    double T[2];
    sph_corrected_iact(nb[k].rij, nb[k].F, nb[k].inv_r2, ps->p[j] - ps->p[i],
                       1.0 / (ps->rho[i] * ps->rho[j]), vv, 2.0 * nu / ps->rho[j], &c, T);
    if (sp->av_alpha > 0) {
      const double ve[2] = {ps->v_est[i][0] - ps->v_est[j][0], ps->v_est[i][1] - ps->v_est[j][1]};
      sph_force_iact_artificial_viscosity(nb[k].rij, nb[k].r * nb[k].r, nb[k].dwdr / nb[k].r,
                                          ps->rho[i], ps->rho[j], ve, sp->av_alpha, sp->av_beta, c0,
                                          h, T);
    }
    a[0] += ps->mass[j] * T[0];
    a[1] += ps->mass[j] * T[1];
  }
  *drho = -ps->rho[i] * c.div;
}

static void test_corrected_sweep(void **state) {
  (void)state;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  unit_rng g = {31};
  static sim s;
  static sph_force_work work;
  static sph_correction_work cw;
  for (int k = 0; k < 3; k++)
    for (int av = 0; av < 2; av++) {
      build_cloud(&s, 150, kernels[k], av ? 0.5 : 0.0, SPH_DENSITY_CONTINUITY, &g);
      /* the continuity velocity is v_est, the viscous one v_visc: make them one (liquid) */
      OK(PetscArraycpy(s.ps.v_visc, s.ps.v_est, s.ps.n_owned + s.ps.n_ghost));
      sph_p.kernel_correction = PETSC_TRUE;
      OK(sph_correction_compute(&s, &sph_p, (const double(*)[2])s.ps.v_visc, &cw));
      OK(sph_force_compute(&s, &sph_p, &work, cw.corr, (const double(*)[2])cw.pair));
      double amax = 0, dmax = 0;
      for (PetscInt i = 0; i < s.ps.n_owned; i++) {
        amax = fmax(amax, fmax(fabs(s.ps.a[i][0]), fabs(s.ps.a[i][1])));
        dmax = fmax(dmax, fabs(s.ps.drho[i]));
      }
      assert_true(amax > 0 && dmax > 0);
      for (PetscInt i = 0; i < s.ps.n_owned; i++) {
        double a[2], drho;
        brute_force_corrected(&s, i, a, &drho);
        assert_close(s.ps.a[i][0], a[0], 1e-12 * amax);
        assert_close(s.ps.a[i][1], a[1], 1e-12 * amax);
        assert_close(s.ps.drho[i], drho, 1e-12 * dmax);
      }
      destroy_cloud(&s);
    }
  OK(sph_correction_destroy(&cw));
}

/* The vectorised sweep over cell ranges (sph_force_cells.c) against the pair-list
 * sweep: the same bits for every kernel it covers, density form, artificial
 * viscosity, density diffusion, with walls in the cloud and one particle turned
 * into a wall after the build (the diffusion follows the current type); with the rows in
 * any order, sorted by cell as the runs sort them, and sorted with runs of owned rows that
 * go on from one row of cells into the next (its copy moves a row of cells at a time); and
 * with the rates left unset for it to set (sim's rates_unset) instead of zeroed. */
static void test_cells_sweep_bitwise(void **state) {
  (void)state;
  if (!sph_force_cells_available())
    skip();
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_WENDLAND};
  unit_rng g = {77};
  static sim s;
  static sph_force_work work;
  int compared = 0, crossing = 0;
  for (int layout = 0; layout < 3; layout++)
    for (int k = 0; k < 2; k++)
      for (int dens = 0; dens < 3; dens++)
        for (int av = 0; av < 2; av++)
          for (int walls = 0; walls < 2; walls++) {
            cloud_walls = walls;
            cloud_layout = layout;
            build_cloud(&s, 400, kernels[k], av ? 0.5 : 0.0,
                        dens ? SPH_DENSITY_CONTINUITY : SPH_DENSITY_SUMMATION, &g);
            cloud_walls = 0;
            cloud_layout = 0;
            sph_p.delta = dens == 2 ? 0.1 : 0.0;
            if (walls)
              s.ps.type[5] = PTYPE_WALL;
            /* a run of consecutive rows across the end of a row of cells */
            for (PetscInt seg = 0; seg < s.cel.n_seg; seg++)
              for (PetscInt cy = 1; cy < s.cel.n[1]; cy++) {
                const PetscInt edge = s.cel.start[cy * s.cel.n[0]];
                crossing += s.cel.seg_pos[seg] < edge && s.cel.seg_pos[seg + 1] > edge;
              }
            const PetscInt rows = s.ps.n_owned + s.ps.n_ghost;
            double(*a_pairs)[2], *d_pairs;
            OK(PetscMalloc2(rows, &a_pairs, rows, &d_pairs));
            sph_p.sweep = SPH_SWEEP_PAIRS;
            OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
            OK(PetscArraycpy(a_pairs, s.ps.a, rows));
            OK(PetscArraycpy(d_pairs, s.ps.drho, rows));
            if (layout == 1 && dens) {
              /* the rates not zeroed, the sweep told to set them (MODULE_SETS_RATES) */
              for (PetscInt i = 0; i < rows; i++)
                s.ps.a[i][0] = s.ps.a[i][1] = s.ps.drho[i] = 1e30;
              s.rates_unset = PETSC_TRUE;
            } else {
              OK(PetscArrayzero(s.ps.a, rows));
              OK(PetscArrayzero(s.ps.drho, rows));
            }
            sph_p.sweep = SPH_SWEEP_CELLS;
            OK(sph_force_compute(&s, &sph_p, &work, NULL, NULL));
            assert_false(s.rates_unset);
            double amax = 0;
            for (PetscInt i = 0; i < s.ps.n_owned; i++) {
              assert_memory_equal(s.ps.a[i], a_pairs[i], sizeof(double[2]));
              assert_memory_equal(&s.ps.drho[i], &d_pairs[i], sizeof(double));
              amax = fmax(amax, fabs(a_pairs[i][0]));
            }
            assert_true(amax > 0);
            compared++;
            OK(PetscFree2(a_pairs, d_pairs));
            destroy_cloud(&s);
          }
  assert_int_equal(compared, 72);
  assert_true(crossing > 0);
  if (work.cells)
    OK(sph_cells_work_destroy(work.cells));
  OK(PetscFree(work.cells));
}

/* ---- Monaghan's artificial pressure ---- */

static void test_tensile_pair(void **state) {
  (void)state;
  unit_rng g = {5};
  const double eps = 0.2, dx = 0.4 * h;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  for (int trial = 0; trial < 600; trial++) {
    const sph_kernel_kind k = kernels[trial % 3];
    const pair_state P = random_pair(&g, k);
    const double norm = sph_kernel_norm(k, 2, h), grad = P.dwdr / P.r;
    double w = 0, dw = 0, w_dx = 0, dw_dx = 0;
    sph_kernel_eval(k, 2, norm, 1.0 / h, P.r, &w, &dw);
    sph_kernel_eval(k, 2, norm, 1.0 / h, dx, &w_dx, &dw_dx);
    /* half the pairs with one particle under tension */
    const double Pi = trial % 2 ? -fabs(P.p_i) - 1.0 : fabs(P.p_i), Pj = fabs(P.p_j);
    const double R_sum =
        sph_tensile_R(eps, Pi / (P.rho_i * P.rho_i)) + sph_tensile_R(eps, Pj / (P.rho_j * P.rho_j));
    const double rji[2] = {-P.rij[0], -P.rij[1]};
    double Tij[2], Tji[2];
    sph_tensile_iact(P.rij, grad, w, 1.0 / w_dx, R_sum, Tij);
    sph_tensile_iact(rji, grad, w, 1.0 / w_dx, R_sum, Tji);
    assert_true(Tji[0] == -Tij[0] && Tji[1] == -Tij[1]);
    if (trial % 2) /* tension: pushed apart */
      assert_true(Tij[0] * P.rij[0] + Tij[1] * P.rij[1] > 0.0);
    else
      assert_true(Tij[0] == 0.0 && Tij[1] == 0.0);
  }
  /* at r = dx, f = 1: the term is R grad r_ij with the sign of a repulsion */
  const double norm = sph_kernel_norm(SPH_KERNEL_LUCY, 2, h), rij[2] = {0.6 * dx, 0.8 * dx};
  double w = 0, dw = 0, T[2];
  sph_kernel_eval(SPH_KERNEL_LUCY, 2, norm, 1.0 / h, dx, &w, &dw);
  const double R = sph_tensile_R(eps, -3.0);
  assert_close(R, 0.6, 1e-15);
  sph_tensile_iact(rij, dw / dx, w, 1.0 / w, R, T);
  assert_close(T[0], -R * (dw / dx) * rij[0], 1e-14 * fabs(T[0]));
  assert_close(T[1], -R * (dw / dx) * rij[1], 1e-14 * fabs(T[1]));
}

/* The pass on a random cloud: a brute-force minimum-image sum per particle, momentum
 * conserved; with every density at or above rho0 (no tension) nothing changes. */
static void test_tensile_pass(void **state) {
  (void)state;
  unit_rng g = {99};
  static sim s;
  static sph_tensile_work work;
  const double eps = 0.2, dx = 0.4 * h;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  for (int k = 0; k < 3; k++) {
    build_cloud(&s, 150, kernels[k], 0.0, SPH_DENSITY_CONTINUITY, &g);
    s.dx = dx;
    sph_p.tensile_eps = eps;
    OK(sph_tensile_compute(&s, &sph_p, &work));
    const double norm = sph_kernel_norm(kernels[k], 2, h);
    double w_dx = 0, dw_dx = 0, P[2] = {0, 0}, scale = 0, amax = 0;
    sph_kernel_eval(kernels[k], 2, norm, 1.0 / h, dx, &w_dx, &dw_dx);
    for (PetscInt i = 0; i < s.ps.n_owned; i++)
      for (int d = 0; d < 2; d++) {
        P[d] += s.ps.mass[i] * s.ps.a[i][d];
        scale += fabs(s.ps.mass[i] * s.ps.a[i][d]);
        amax = fmax(amax, fabs(s.ps.a[i][d]));
      }
    assert_true(scale > 0);
    assert_true(fabs(P[0]) <= 1e-12 * scale && fabs(P[1]) <= 1e-12 * scale);
    for (PetscInt i = 0; i < s.ps.n_owned; i++) {
      double a[2] = {0, 0};
      for (PetscInt j = 0; j < s.ps.n_owned; j++) {
        if (j == i)
          continue;
        double rij[2] = {s.ps.x[i][0] - s.ps.x[j][0], s.ps.x[i][1] - s.ps.x[j][1]};
        domain_min_image(&s.dom, rij);
        const double r = hypot(rij[0], rij[1]);
        if (r >= h)
          continue;
        double w = 0, dw = 0;
        sph_kernel_eval(kernels[k], 2, norm, 1.0 / h, r, &w, &dw);
        /* Monaghan (2000) written out here, independently of sph_tensile_iact */
        const double Ri = s.ps.p[i] < 0 ? -eps * s.ps.p[i] / (s.ps.rho[i] * s.ps.rho[i]) : 0;
        const double Rj = s.ps.p[j] < 0 ? -eps * s.ps.p[j] / (s.ps.rho[j] * s.ps.rho[j]) : 0;
        const double f = pow(w / w_dx, 4.0);
        for (int d = 0; d < 2; d++)
          a[d] -= s.ps.mass[j] * (Ri + Rj) * f * (dw / r) * rij[d];
      }
      assert_close(s.ps.a[i][0], a[0], 1e-12 * amax);
      assert_close(s.ps.a[i][1], a[1], 1e-12 * amax);
    }
    /* no tension anywhere: the pass adds nothing */
    for (PetscInt i = 0; i < s.ps.n_owned + s.ps.n_ghost; i++)
      s.ps.p[i] = fabs(s.ps.p[i]);
    OK(PetscArrayzero(s.ps.a, s.ps.n_owned + s.ps.n_ghost));
    OK(sph_tensile_compute(&s, &sph_p, &work));
    for (PetscInt i = 0; i < s.ps.n_owned; i++)
      assert_true(s.ps.a[i][0] == 0.0 && s.ps.a[i][1] == 0.0);
    sph_p.tensile_eps = 0.0;
    destroy_cloud(&s);
  }
  OK(sph_tensile_destroy(&work));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pair_antisymmetry),
      cmocka_unit_test(test_artificial_viscosity_only_when_approaching),
      cmocka_unit_test(test_pressure_repels),
      cmocka_unit_test(test_sweep_conserves_momentum),
      cmocka_unit_test(test_summation_density),
      cmocka_unit_test(test_coincident_pair),
      cmocka_unit_test(test_corrected_sweep),
      cmocka_unit_test(test_cells_sweep_bitwise),
      cmocka_unit_test(test_tensile_pair),
      cmocka_unit_test(test_tensile_pass),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
