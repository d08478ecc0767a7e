/* Wall boundary values (src/physics/sph_wall.c, Adami, Hu & Adams 2012):
 *   p_w      = [sum_f p_f W_wf + g . sum_f rho_f (x_w - x_f) W_wf] / sum_f W_wf
 *   v_visc_w = 2 v_w - sum_f v_f W_wf / sum_f W_wf
 *   rho_w    = EOS^-1(p_w - p_b)
 * on configurations whose weighted averages need no kernel value, so that the
 * expected numbers are computed by hand:
 *   - a wall particle under a row of liquid at one height d above it, at
 *     uniform pressure p0 and at rest (or moving uniformly), with gravity:
 *     p_w = p0 + rho g d (the hydrostatic term; a horizontal component of g
 *     cancels on the symmetric row), v_visc = 2 v_w - u (no-slip mirror),
 *     rho_w from the linear shifted EOS with a background pressure; for every
 *     kernel; the same across a periodic boundary (liquid images), where the
 *     wall's own ghost gets the wall's values;
 *   - two liquid particles at the same distance, one above and one beside the
 *     wall: the plain average of p and v plus half of rho_1 g d;
 *   - liquid only in the pair list's skin (r > h) does not count: the wall
 *     keeps rho0, EOS(rho0) + p_b and its own velocity;
 *   - wall-wall neighbours do not count; liquid rows keep v_visc = v_est;
 *   - -sph_wall_extrapolation quadratic without a surface vector is Adami's. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "physics/sph_force.h"
#include "physics/sph_eos.h"

static const double h = 0.01, rho0 = 1000.0, c0 = 2.0, p_b = 3.0;

typedef struct {
  double x[2], v[2], rho, p;
  particle_type type;
} spec;

static sim s;
/* the liquid's parameters and the body acceleration, passed to the wall pass as the sph
 * module does */
static sph_params sph_p;
static double g_body[2];

/* A sim with the given particles (closed box [0, 1]^2, or periodic in x),
 * ghosts and the pair list to 1.2 h (liquid between h and 1.2 h is in the
 * list's skin only). */
static void build(const spec *sp, int n, sph_kernel_kind kernel, const double g[2],
                  PetscBool periodic_x, sph_wall_kind wall) {
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  sph_p = (sph_params){.kernel = kernel,
                       .h = h,
                       .rho0 = rho0,
                       .c0 = c0,
                       .nu = 1e-6,
                       .eos = SPH_EOS_LINEAR_SHIFTED,
                       .density = SPH_DENSITY_CONTINUITY,
                       .p_background = p_b,
                       .wall = wall};
  s.dx = h / 3;
  s.dom = (domain){.lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .periodic = {periodic_x, PETSC_FALSE}};
  g_body[0] = g[0];
  g_body[1] = g[1];
  fields_reset();
  OK(fields_enable("v_visc")); /* what the wall pass extrapolates */
  OK(unit_enable_sph_fields());
  if (wall == SPH_WALL_QUADRATIC)
    OK(fields_enable("to_surface"));
  OK(particles_create(&s.ps));
  for (int k = 0; k < n; k++) {
    PetscInt i;
    double x[2] = {sp[k].x[0], sp[k].x[1]};
    domain_wrap(&s.dom, x);
    OK(particles_add_owned(&s.ps, 100 + k, sp[k].type, x, sp[k].v, 1e-3, sp[k].rho, &i));
    s.ps.p[i] = sp[k].p;
  }
  const double cut = 1.2 * h;
  OK(halo_create(&s.hal, cut, PETSC_COMM_SELF));
  OK(halo_build(&s.hal, &s.dom, NULL, &s.ps));
  OK(cells_create(&s.cel));
  const double lo[2] = {-cut, -cut}, hi[2] = {1.0 + cut, 1.0 + cut};
  OK(cells_build_pairs(&s.cel, &s.ps, lo, hi, cut));
}

static void compute(void) {
  sph_wall_work *w;
  OK(sph_wall_create(&w));
  OK(sph_wall_compute(&s, &sph_p, g_body, w));
  OK(sph_wall_destroy(&w));
}

static void destroy(void) {
  OK(cells_destroy(&s.cel));
  OK(halo_destroy(&s.hal));
  OK(particles_destroy(&s.ps));
  fields_reset();
}

static double rho_of(double p) {
  return rho0 + (p - p_b) / (c0 * c0);
} /* linear shifted, by hand */

static const sph_kernel_kind kernels[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};

/* A wall at (xw, 0.1) moving at vw; under it, at height d = 0.3 h, liquid at
 * xw + j h/4, j = -3..3 (all within h), pressure p0, density rho, velocity u;
 * a second wall 0.3 h to the right; a liquid particle 1.1 h above the wall
 * (in the skin) with a pressure and velocity that would show. */
static int row_case(spec *sp, double xw, const double vw[2], const double u[2], double p0,
                    double rho) {
  int n = 0;
  const double d = 0.3 * h;
  sp[n++] = (spec){{xw, 0.1}, {vw[0], vw[1]}, rho0, 0.0, PTYPE_WALL};
  sp[n++] = (spec){{xw + 0.3 * h, 0.1}, {-5.0, 7.0}, rho0, 1e6, PTYPE_WALL};
  for (int j = -3; j <= 3; j++)
    sp[n++] = (spec){{xw + 0.25 * h * j, 0.1 + d}, {u[0], u[1]}, rho, p0, PTYPE_FLUID};
  sp[n++] = (spec){{xw, 0.1 + 1.1 * h}, {40.0, -40.0}, rho, 1e6, PTYPE_FLUID};
  return n;
}

static void check_wall(PetscInt i, double p, const double v_visc[2]) {
  const double tol = 1e-12 * (fabs(p) + 1.0);
  assert_close(s.ps.p[i], p, tol);
  assert_close(s.ps.rho[i], rho_of(p), 1e-12 * rho0);
  assert_close(s.ps.v_visc[i][0], v_visc[0], 1e-12);
  assert_close(s.ps.v_visc[i][1], v_visc[1], 1e-12);
}

static void test_hydrostatic_row(void **state) {
  (void)state;
  const double d = 0.3 * h, p0 = 150.0, rho = 1001.5, gy = 9.81;
  const double vw[2] = {0.02, 0.0}, g[2] = {0.4, -gy};
  const double rest[2] = {0.0, 0.0}, moving[2] = {0.05, -0.01};
  for (int ik = 0; ik < 3; ik++)
    for (int mv = 0; mv < 2; mv++) {
      spec sp[16];
      const double *u = mv ? moving : rest;
      const int n = row_case(sp, 0.5, vw, u, p0, rho);
      build(sp, n, kernels[ik], g, PETSC_FALSE, SPH_WALL_ADAMI);
      compute();
      /* g . (x_w - x_f) = (0.4)(-j h/4) + (-gy)(-d): the x parts cancel over j = -3..3 */
      const double p = p0 + rho * gy * d, v_visc[2] = {2 * vw[0] - u[0], 2 * vw[1] - u[1]};
      check_wall(0, p, v_visc);
      /* the liquid sees its own predicted velocity */
      for (PetscInt f = 2; f < n; f++) {
        assert_true(s.ps.v_visc[f][0] == s.ps.v_est[f][0] && s.ps.v_visc[f][1] == s.ps.v_est[f][1]);
        assert_true(s.ps.p[f] == (f == n - 1 ? 1e6 : p0)); /* liquid values untouched */
      }
      destroy();
    }
}

/* Without the horizontal g, the second wall (0.3 h to the right, still under
 * the same row) gets the same hydrostatic value: the other wall's 1e6 Pa is not
 * averaged in. */
static void test_second_wall(void **state) {
  (void)state;
  const double d = 0.3 * h, p0 = -20.0, rho = 999.0, g[2] = {0.0, -2.0};
  const double vw[2] = {0.0, 0.0}, u[2] = {0.01, 0.0};
  spec sp[16];
  const int n = row_case(sp, 0.5, vw, u, p0, rho);
  build(sp, n, SPH_KERNEL_WENDLAND, g, PETSC_FALSE, SPH_WALL_ADAMI);
  compute();
  const double p = p0 + rho * 2.0 * d;
  check_wall(0, p, (double[2]){-u[0], -u[1]});
  check_wall(1, p, (double[2]){2 * -5.0 - u[0], 2 * 7.0 - u[1]});
  destroy();
}

/* The same row across the periodic boundary x = 0: the liquid left of the wall
 * are images; the result is the closed box's, and the wall's own image (a
 * ghost, within the ghost width of x = 1) carries the wall's values. */
static void test_periodic_images(void **state) {
  (void)state;
  const double d = 0.3 * h, p0 = 80.0, rho = 1000.2, g[2] = {0.0, -9.81};
  const double vw[2] = {-0.01, 0.0}, u[2] = {0.03, 0.0};
  for (int ik = 0; ik < 3; ik++) {
    spec sp[16];
    const int n = row_case(sp, 0.1 * h, vw, u, p0, rho);
    build(sp, n, kernels[ik], g, PETSC_TRUE, SPH_WALL_ADAMI);
    assert_true(s.ps.n_ghost > 0);
    compute();
    const double p = p0 + rho * 9.81 * d, v_visc[2] = {2 * vw[0] - u[0], -u[1]};
    check_wall(0, p, v_visc);
    int images = 0;
    for (PetscInt gh = 0; gh < s.hal.n; gh++) {
      if (s.hal.source[gh] != 0)
        continue;
      const PetscInt row = s.ps.n_owned + gh;
      assert_true(s.ps.p[row] == s.ps.p[0] && s.ps.rho[row] == s.ps.rho[0]);
      assert_true(s.ps.v_visc[row][0] == s.ps.v_visc[0][0] &&
                  s.ps.v_visc[row][1] == s.ps.v_visc[0][1]);
      images++;
    }
    assert_int_equal(images, 1);
    destroy();
  }
}

/* Two liquid particles at the same distance d from the wall, one above it and
 * one beside it: equal kernel weights, so plain averages. */
static void test_two_equidistant(void **state) {
  (void)state;
  const double d = 0.45 * h, gy = 5.0, g[2] = {0.0, -gy};
  const double p1 = 10.0, p2 = 30.0, r1 = 1002.0, r2 = 998.0;
  const double v1[2] = {0.1, 0.02}, v2[2] = {-0.04, 0.06}, vw[2] = {0.01, -0.02};
  for (int ik = 0; ik < 3; ik++) {
    const spec sp[3] = {{{0.5, 0.5}, {vw[0], vw[1]}, rho0, 0.0, PTYPE_WALL},
                        {{0.5, 0.5 + d}, {v1[0], v1[1]}, r1, p1, PTYPE_FLUID},
                        {{0.5 + d, 0.5}, {v2[0], v2[1]}, r2, p2, PTYPE_FLUID}};
    build(sp, 3, kernels[ik], g, PETSC_FALSE, SPH_WALL_ADAMI);
    compute();
    /* g . (x_w - x_1) = gy d, g . (x_w - x_2) = 0 */
    const double p = 0.5 * (p1 + p2) + 0.5 * r1 * gy * d;
    check_wall(0, p,
               (double[2]){2 * vw[0] - 0.5 * (v1[0] + v2[0]), 2 * vw[1] - 0.5 * (v1[1] + v2[1])});
    destroy();
  }
}

/* Liquid only between h and 1.2 h (in the list, outside the support): the wall
 * keeps rho0, p = EOS(rho0) + p_b = p_b, and v_visc = its own velocity. */
static void test_no_liquid_in_support(void **state) {
  (void)state;
  const double g[2] = {0.0, -9.81};
  const spec sp[3] = {{{0.5, 0.5}, {0.03, 0.0}, 1010.0, 77.0, PTYPE_WALL},
                      {{0.5, 0.5 + 1.05 * h}, {1.0, 1.0}, 1000.0, 500.0, PTYPE_FLUID},
                      {{0.5 - 0.8 * h, 0.5 - 0.8 * h}, {1.0, 1.0}, 1000.0, 500.0, PTYPE_FLUID}};
  build(sp, 3, SPH_KERNEL_CUBIC, g, PETSC_FALSE, SPH_WALL_ADAMI);
  assert_int_equal(s.cel.n_pairs, 2); /* both wall-liquid pairs are listed (r < 1.2 h) */
  compute();
  assert_close(s.ps.rho[0], rho0, 0);
  assert_close(s.ps.p[0], p_b, 0);
  assert_close(s.ps.v_visc[0][0], 0.03, 0);
  assert_close(s.ps.v_visc[0][1], 0.0, 0);
  destroy();
}

/* -sph_wall_extrapolation quadratic on walls without a surface vector: Adami's values. */
static void test_quadratic_without_geometry(void **state) {
  (void)state;
  const double d = 0.3 * h, p0 = 150.0, rho = 1001.5, g[2] = {0.0, -9.81};
  const double vw[2] = {0.02, 0.0}, u[2] = {0.05, -0.01};
  spec sp[16];
  const int n = row_case(sp, 0.5, vw, u, p0, rho);
  build(sp, n, SPH_KERNEL_WENDLAND, g, PETSC_FALSE, SPH_WALL_QUADRATIC);
  assert_non_null(s.ps.to_surface);
  compute();
  check_wall(0, p0 + rho * 9.81 * d, (double[2]){2 * vw[0] - u[0], 2 * vw[1] - u[1]});
  destroy();
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_hydrostatic_row),
      cmocka_unit_test(test_second_wall),
      cmocka_unit_test(test_periodic_images),
      cmocka_unit_test(test_two_equidistant),
      cmocka_unit_test(test_no_liquid_in_support),
      cmocka_unit_test(test_quadratic_without_geometry),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
