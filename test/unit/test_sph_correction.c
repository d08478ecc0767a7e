/* The corrected SPH operators (src/physics/sph_correction_iact.h,
 * -sph_kernel_correction). Proves, on a patch of particles displaced at random
 * from a square lattice (up to 0.25 dx, masses and densities varied by +-3 %),
 * for each kernel and at every particle whose support lies inside the patch:
 *   - the pressure term is -grad p/rho_i to round-off for a linear p, and zero
 *     for a uniform p (any background pressure: the plain symmetric form
 *     is not, which is what drifts on a sheared lattice);
 *   - the viscous term is nu lap v to round-off for a quadratic v (both
 *     components, every second derivative non-zero), which Morris' form misses
 *     by more than 1e-3 on the same patch;
 *   - the corrected divergence is exact for a linear v;
 * and that listing a pair the other way round gives bit for bit the same
 * moments and the same pair term for each side (rank-count invariance), and
 * that a particle with too few neighbours falls back to the plain operators. */
#include "unit_common.h"
#include "physics/sph_correction_iact.h"

static const double dx = 0.01, rho0 = 1000.0, nu = 1e-3;
#define NSIDE 16
#define NP    (NSIDE * NSIDE)

typedef struct {
  double x[NP][2], m[NP], rho[NP];
} patch;

static void make_patch(patch *P, unit_rng *g) {
  for (int a = 0; a < NSIDE; a++)
    for (int b = 0; b < NSIDE; b++) {
      const int k = a * NSIDE + b;
      P->x[k][0] = (a + unit_range(g, -0.25, 0.25)) * dx;
      P->x[k][1] = (b + unit_range(g, -0.25, 0.25)) * dx;
      P->rho[k] = rho0 * unit_range(g, 0.97, 1.03);
      P->m[k] = rho0 * dx * dx * unit_range(g, 0.97, 1.03);
    }
}

/* linear pressure, quadratic velocity with every coefficient non-zero */
static double p_of(const double x[2]) {
  return 5.0 + 300.0 * x[0] - 200.0 * x[1];
}
static void v_of(const double x[2], double v[2]) {
  v[0] =
      0.1 + 2.0 * x[0] - 1.0 * x[1] + 30.0 * x[0] * x[0] - 20.0 * x[0] * x[1] + 10.0 * x[1] * x[1];
  v[1] =
      -0.2 + 1.5 * x[0] + 0.5 * x[1] - 15.0 * x[0] * x[0] + 25.0 * x[0] * x[1] + 40.0 * x[1] * x[1];
}
static const double lap_v[2] = {2 * 30.0 + 2 * 10.0, 2 * -15.0 + 2 * 40.0};

static int inside(const double x[2], double h) {
  const double lo = h + 0.3 * dx, hi = (NSIDE - 1) * dx - h - 0.3 * dx;
  return x[0] > lo && x[0] < hi && x[1] > lo && x[1] < hi;
}

static void pair_geometry(const patch *P, int i, int j, sph_kernel_kind kernel, double h,
                          double xij[2], double *F, double *inv_r2, double *dwdr) {
  xij[0] = P->x[i][0] - P->x[j][0];
  xij[1] = P->x[i][1] - P->x[j][1];
  const double r2 = xij[0] * xij[0] + xij[1] * xij[1], r = sqrt(r2);
  double w;
  sph_kernel_eval(kernel, 2, sph_kernel_norm(kernel, 2, h), 1.0 / h, r, &w, dwdr);
  *inv_r2 = 1.0 / r2;
  *F = *dwdr * (r * *inv_r2);
}

/* the moments and the correction of particle i; vfield gives the velocity */
static void correction_of(const patch *P, int i, sph_kernel_kind kernel, double h,
                          sph_correction *c, int *ok) {
  sph_moments m = {0};
  double vi[2];
  v_of(P->x[i], vi);
  for (int j = 0; j < NP; j++) {
    if (j == i || hypot(P->x[i][0] - P->x[j][0], P->x[i][1] - P->x[j][1]) >= h)
      continue;
    double xij[2], F, inv_r2, dwdr, vj[2];
    pair_geometry(P, i, j, kernel, h, xij, &F, &inv_r2, &dwdr);
    v_of(P->x[j], vj);
    const double vji[2] = {vj[0] - vi[0], vj[1] - vi[1]};
    sph_moments_pair(xij, F, inv_r2, vji, P->m[j] / P->rho[j], &m);
  }
  *ok = sph_correction_from_moments(&m, c);
}

static void test_exact_fields(void **state) {
  (void)state;
  const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  static patch P;
  unit_rng g = {11};
  for (int k = 0; k < 3; k++) {
    make_patch(&P, &g);
    const double h = 3.0 * dx;
    int tested = 0;
    double morris_worst = 0.0;
    for (int i = 0; i < NP; i++) {
      if (!inside(P.x[i], h))
        continue;
      sph_correction c;
      int ok;
      correction_of(&P, i, kernels[k], h, &c, &ok);
      assert_true(ok);
      double ap[2] = {0, 0}, au[2] = {0, 0}, av[2] = {0, 0}, am[2] = {0, 0}, vi[2];
      v_of(P.x[i], vi);
      const double grad_p[2] = {300.0, -200.0};
      for (int j = 0; j < NP; j++) {
        if (j == i || hypot(P.x[i][0] - P.x[j][0], P.x[i][1] - P.x[j][1]) >= h)
          continue;
        double xij[2], F, inv_r2, dwdr, vj[2], T[2];
        pair_geometry(&P, i, j, kernels[k], h, xij, &F, &inv_r2, &dwdr);
        v_of(P.x[j], vj);
        const double vv[2] = {vi[0] - vj[0], vi[1] - vj[1]}, zero[2] = {0, 0};
        const double inv_rho2 = 1.0 / (P.rho[i] * P.rho[j]), mu_sum = 2.0 * rho0 * nu;
        const double nu2_rho = 2.0 * nu / P.rho[j];
        /* pressure alone (mu = 0), uniform pressure alone, viscosity alone (p = 0) */
        sph_corrected_iact(xij, F, inv_r2, p_of(P.x[j]) - p_of(P.x[i]), inv_rho2, zero, 0.0, &c, T);
        ap[0] += P.m[j] * T[0];
        ap[1] += P.m[j] * T[1];
        sph_corrected_iact(xij, F, inv_r2, 0.0, inv_rho2, zero, 0.0, &c, T);
        au[0] += P.m[j] * T[0];
        au[1] += P.m[j] * T[1];
        sph_corrected_iact(xij, F, inv_r2, 0.0, inv_rho2, vv, nu2_rho, &c, T);
        av[0] += P.m[j] * T[0];
        av[1] += P.m[j] * T[1];
        /* Morris (1997) on the same neighbours, for contrast (mu/rho_i -> nu) */
        am[0] += P.m[j] * mu_sum * inv_rho2 * F * vv[0] * P.rho[i] / rho0;
        am[1] += P.m[j] * mu_sum * inv_rho2 * F * vv[1] * P.rho[i] / rho0;
      }
      for (int d = 0; d < 2; d++) {
        /* a uniform pressure enters only through p_j - p_i = 0: exactly zero */
        assert_true(au[d] == 0.0);
        assert_close(ap[d], -grad_p[d] / P.rho[i], 1e-9 * hypot(grad_p[0], grad_p[1]) / rho0);
        /* nu lap v, whatever the densities */
        const double want = nu * lap_v[d];
        assert_close(av[d], want, 1e-8 * fabs(want));
        morris_worst = fmax(morris_worst, fabs(am[d] - want) / fabs(want));
      }
      /* div v of the linear part (2.0 + 0.5) plus the quadratic part at x_i */
      const double div =
          2.0 + 0.5 + 60.0 * P.x[i][0] - 20.0 * P.x[i][1] + 25.0 * P.x[i][0] + 80.0 * P.x[i][1];
      assert_close(c.div, div, 2e-2 * fabs(div)); /* second-order error of a first-order gradient */
      tested++;
    }
    assert_true(tested > 50);
    assert_true(morris_worst > 1e-3); /* the test can tell a corrected Laplacian from a plain one */
  }
}

static void test_linear_divergence_exact(void **state) {
  (void)state;
  static patch P;
  unit_rng g = {5};
  make_patch(&P, &g);
  const double h = 3.0 * dx, A[2][2] = {{0.7, -1.3}, {2.1, 0.4}};
  int tested = 0;
  for (int i = 0; i < NP; i++) {
    if (!inside(P.x[i], h))
      continue;
    sph_moments m = {0};
    for (int j = 0; j < NP; j++) {
      if (j == i || hypot(P.x[i][0] - P.x[j][0], P.x[i][1] - P.x[j][1]) >= h)
        continue;
      double xij[2], F, inv_r2, dwdr;
      pair_geometry(&P, i, j, SPH_KERNEL_WENDLAND, h, xij, &F, &inv_r2, &dwdr);
      const double vji[2] = {-(A[0][0] * xij[0] + A[0][1] * xij[1]),
                             -(A[1][0] * xij[0] + A[1][1] * xij[1])};
      sph_moments_pair(xij, F, inv_r2, vji, P.m[j] / P.rho[j], &m);
    }
    sph_correction c;
    assert_true(sph_correction_from_moments(&m, &c));
    assert_close(c.div, A[0][0] + A[1][1], 1e-10);
    assert_close(c.G[0], A[0][0], 1e-10);
    assert_close(c.G[1], A[0][1], 1e-10);
    assert_close(c.G[2], A[1][0], 1e-10);
    assert_close(c.G[3], A[1][1], 1e-10);
    tested++;
  }
  assert_true(tested > 50);
}

/* One pair listed as (i, j) and as (j, i): each particle's moments and pair
 * term must be the same bits, whichever it is listed as. */
static void test_pair_order_bitwise(void **state) {
  (void)state;
  unit_rng g = {99};
  for (int trial = 0; trial < 2000; trial++) {
    const double h = 0.1, r = unit_range(&g, 0.02, 0.98) * h, phi = unit_range(&g, 0, 2 * M_PI);
    const double xij[2] = {r * cos(phi), r * sin(phi)}, xji[2] = {-xij[0], -xij[1]};
    const double vi[2] = {unit_range(&g, -1, 1), unit_range(&g, -1, 1)};
    const double vj[2] = {unit_range(&g, -1, 1), unit_range(&g, -1, 1)};
    const double pi = unit_range(&g, -5, 5), pj = unit_range(&g, -5, 5);
    const double Vi = unit_range(&g, 0.9, 1.1), Vj = unit_range(&g, 0.9, 1.1);
    double w, dwdr;
    sph_kernel_eval(SPH_KERNEL_LUCY, 2, sph_kernel_norm(SPH_KERNEL_LUCY, 2, h), 1.0 / h, r, &w,
                    &dwdr);
    const double r2a = xij[0] * xij[0] + xij[1] * xij[1], r2b = xji[0] * xji[0] + xji[1] * xji[1];
    assert_true(r2a == r2b);
    const double inv_r2 = 1.0 / r2a, F = dwdr * (sqrt(r2a) * inv_r2);
    /* listed (i, j): i side with (xij, vj - vi), j side with the negations */
    sph_moments mi1 = {0}, mj1 = {0}, mi2 = {0}, mj2 = {0};
    const double vji[2] = {vj[0] - vi[0], vj[1] - vi[1]}, mvji[2] = {-vji[0], -vji[1]};
    sph_moments_pair(xij, F, inv_r2, vji, Vj, &mi1);
    sph_moments_pair(xji, F, inv_r2, mvji, Vi, &mj1);
    sph_moments_pair_wall(xij, F, vji, Vj, &mi1);
    sph_moments_pair_wall(xji, F, mvji, Vi, &mj1);
    /* listed (j, i): the roles swap */
    const double vij[2] = {vi[0] - vj[0], vi[1] - vj[1]}, mvij[2] = {-vij[0], -vij[1]};
    sph_moments_pair(xji, F, inv_r2, vij, Vi, &mj2);
    sph_moments_pair(xij, F, inv_r2, mvij, Vj, &mi2);
    sph_moments_pair_wall(xji, F, vij, Vi, &mj2);
    sph_moments_pair_wall(xij, F, mvij, Vj, &mi2);
    assert_memory_equal(&mi1, &mi2, sizeof(mi1));
    assert_memory_equal(&mj1, &mj2, sizeof(mj1));
    sph_correction ci = {
        .L = {1.1, 0.1, 0.9}, .G = {0.3, -0.2, 0.5, 0.1}, .B = {1.02, -0.01, 0.97}};
    sph_correction cj = {
        .L = {0.95, -0.05, 1.05}, .G = {-0.1, 0.4, 0.2, -0.3}, .B = {0.99, 0.02, 1.01}};
    double Ti1[2], Tj1[2], Ti2[2], Tj2[2];
    sph_corrected_iact(xij, F, inv_r2, pj - pi, 1e-6, vij, 2.0, &ci, Ti1);
    sph_corrected_iact(xji, F, inv_r2, -(pj - pi), 1e-6, mvij, 2.0, &cj, Tj1);
    sph_corrected_iact(xji, F, inv_r2, pi - pj, 1e-6, vji, 2.0, &cj, Tj2);
    sph_corrected_iact(xij, F, inv_r2, -(pi - pj), 1e-6, mvji, 2.0, &ci, Ti2);
    assert_memory_equal(Ti1, Ti2, sizeof(Ti1));
    assert_memory_equal(Tj1, Tj2, sizeof(Tj1));
  }
}

static void test_sparse_falls_back(void **state) {
  (void)state;
  sph_moments m = {0};
  const double x1[2] = {0.01, 0.0}, x2[2] = {-0.01, 0.0}, v[2] = {0.5, -0.5};
  /* two neighbours on a line: M is singular across it */
  sph_moments_pair(x1, -3.0, 1e4, v, 1e-4, &m);
  sph_moments_pair(x2, -3.0, 1e4, v, 1e-4, &m);
  sph_correction c;
  assert_int_equal(sph_correction_from_moments(&m, &c), 0);
  assert_true(c.L[0] == 1.0 && c.L[1] == 0.0 && c.L[2] == 1.0);
  assert_true(c.B[0] == 1.0 && c.B[1] == 0.0 && c.B[2] == 1.0);
  assert_true(c.G[0] == 0.0 && c.G[1] == 0.0 && c.G[2] == 0.0 && c.G[3] == 0.0);
  assert_true(c.div == m.g[0] + m.g[3]); /* the plain SPH divergence */
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_exact_fields),
      cmocka_unit_test(test_linear_divergence_exact),
      cmocka_unit_test(test_pair_order_bitwise),
      cmocka_unit_test(test_sparse_falls_back),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
