/* The solids' fastest mode (src/core/solid_modes.c): exact for a bond between
 * two free particles and for one held by a wall; for the vein's two-layer
 * leaflet at its study spacing an upper bound within 1.3x of the fastest mode
 * found by power iteration on the modules' own forces, which lies several
 * times above the per-spring estimate the sub-step limits use; and the step's
 * limit 1.25/omega is added, bounding dt itself, only with sub-steps. */
#include "solid_fixture.h"
#include "dmhs/dt_limits.h"
#include "dmhs/timestep.h"
#include "dmhs/solid_modes.h"
#include "scenes/solid_strip.h"

static void test_dimer(void **state) {
  (void)state;
  const double zero[2] = {0, 0}, K = 1e6, r0 = 1e-4, m = 2e-5;
  for (int held = 0; held < 2; held++) {
    sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
    OK(modules_enable(s, "bond_harmonic", NULL));
    OK(bond_set_default(s, K, r0, 0));
    const double xa[2] = {4e-3, 5e-3}, xb[2] = {4e-3 + r0, 5e-3};
    OK(particles_add_owned(&s->ps, 0, held ? PTYPE_WALL : PTYPE_SOLID, xa, zero, m, 1000, NULL));
    OK(particles_add_owned(&s->ps, 1, PTYPE_SOLID, xb, zero, m, 1000, NULL));
    OK(topology_add_bond(s->topo, 0, 1, 0));
    fixture_setup(s);
    double omega;
    OK(solid_modes_omega_bound(s, &omega));
    /* U = K x^2: k = 2K on the reduced mass m/2 (free), on m (held) */
    const double exact = held ? sqrt(2 * K / m) : sqrt(4 * K / m);
    assert_true(fabs(omega - exact) < 1e-12 * exact);
    fixture_destroy(&s);
  }
}

/* a = M^-1 F at the current positions, into out (owned rows) */
static void accelerations(sim *s, double (*out)[2]) {
  OK(neighbours_rebuild(s));
  OK(sim_compute_forces(s));
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    out[i][0] = s->ps.a[i][0];
    out[i][1] = s->ps.a[i][1];
  }
}

/* The largest eigenvalue of M^-1 H over the moving rows by power iteration, H v from
 * central differences of the forces; returns its Rayleigh quotient (a lower bound). */
static double fastest_mode_power(sim *s, int iterations) {
  const PetscInt n = s->ps.n_owned;
  double(*x0)[2], (*v)[2], (*ap)[2], (*am)[2];
  OK(PetscMalloc4(n, &x0, n, &v, n, &ap, n, &am));
  unsigned long long seed = 777;
  for (PetscInt i = 0; i < n; i++)
    for (int c = 0; c < 2; c++) {
      x0[i][c] = s->ps.x[i][c];
      v[i][c] = s->ps.type[i] == PTYPE_WALL ? 0 : fixture_rand(&seed);
    }
  double lambda = 0;
  const double eps = 1e-9; /* [m]: 5e-6 of the spacing */
  for (int it = 0; it < iterations; it++) {
    double norm = 0;
    for (PetscInt i = 0; i < n; i++)
      norm += v[i][0] * v[i][0] + v[i][1] * v[i][1];
    norm = sqrt(norm);
    for (PetscInt i = 0; i < n; i++)
      for (int c = 0; c < 2; c++) {
        v[i][c] /= norm;
        s->ps.x[i][c] = x0[i][c] + eps * v[i][c];
      }
    accelerations(s, ap);
    for (PetscInt i = 0; i < n; i++)
      for (int c = 0; c < 2; c++)
        s->ps.x[i][c] = x0[i][c] - eps * v[i][c];
    accelerations(s, am);
    lambda = 0;
    for (PetscInt i = 0; i < n; i++)
      for (int c = 0; c < 2; c++) {
        const double hv = s->ps.type[i] == PTYPE_WALL ? 0 : -(ap[i][c] - am[i][c]) / (2 * eps);
        lambda += v[i][c] * hv;
        v[i][c] = hv;
      }
  }
  for (PetscInt i = 0; i < n; i++)
    for (int c = 0; c < 2; c++)
      s->ps.x[i][c] = x0[i][c];
  OK(PetscFree4(x0, v, ap, am));
  return lambda;
}

/* the vein's leaflet at dx = 2e-4 m with run 32's angles (input/vein-run32.opts) */
static sim *leaflet(PetscInt substeps, double *ka, double *r0, double *m) {
  *ka = 0.025;
  *r0 = 2e-4;
  *m = 8e-5;
  sim *s = fixture_create(2e-2, 1e-2, PETSC_FALSE);
  fixture_substeps(s, substeps);
  OK(modules_enable(s, "bond_harmonic", NULL));
  OK(modules_enable(s, "angle_harmonic", NULL));
  OK(bond_set_default(s, 1.25e5, *r0, 0));
  OK(angle_set_default(s, *ka, 90.0));
  solid_strip st = {.n = 40,
                    .n_clamp = 1,
                    .origin = {2e-3, 5e-3},
                    .along = {1, 0},
                    .across = {0, 1},
                    .spacing = *r0,
                    .mass = *m,
                    .rho = 1000};
  PetscInt64 gid = 0;
  OK(solid_strip_build(s, &st, &gid));
  fixture_setup(s);
  return s;
}

static void test_leaflet_bound(void **state) {
  (void)state;
  double ka, r0, m, omega;
  sim *s = leaflet(1, &ka, &r0, &m);
  OK(solid_modes_omega_bound(s, &omega));
  const double fastest = sqrt(fastest_mode_power(s, 3000));
  const double spring = sqrt(2 * ka / (r0 * r0) / m); /* the angle's sub-step estimate */
  print_message("fastest mode %.4g 1/s (power iteration), bound %.4g (%.3fx), spring %.4g\n",
                fastest, omega, omega / fastest, spring);
  assert_true(omega >= fastest * (1 - 1e-6));
  assert_true(omega <= 1.3 * fastest);
  assert_true(fastest > 3 * spring);
  fixture_destroy(&s);
}

static const dt_limit *find_limit(const dt_limits *l, const char *name) {
  for (int k = 0; k < l->n; k++)
    if (!strcmp(l->item[k].name, name))
      return &l->item[k];
  return NULL;
}

static void test_limit_with_substeps(void **state) {
  (void)state;
  double ka, r0, m, omega;
  for (int sub = 0; sub < 2; sub++) {
    sim *s = leaflet(sub ? 0 : 1, &ka, &r0, &m);
    dt_limits l;
    OK(timestep_collect_limits(s, &l));
    const dt_limit *mode = find_limit(&l, "solid fastest mode");
    if (!sub) {
      assert_null(mode);
    } else {
      OK(solid_modes_omega_bound(s, &omega));
      assert_non_null(mode);
      assert_false(mode->inner); /* it bounds dt, not the sub-step */
      const double want = SOLID_MODES_LIMIT / omega;
      assert_true(mode->value <= want && mode->value > want * (1 - 1e-6));
      assert_true(find_limit(&l, "angle harmonic")->inner);
    }
    fixture_destroy(&s);
  }
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_dimer),
      cmocka_unit_test(test_leaflet_bound),
      cmocka_unit_test(test_limit_with_substeps),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(events_register());
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
