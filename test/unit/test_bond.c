/* Bond potentials: force = -grad U (finite differences) for the harmonic and
 * nonlinear bonds; the nonlinear bond's stiffness is U''; a bond stretched
 * past r_max stops with an error (not NaN), one past 0.95 r_max only warns. */
#include "solid_fixture.h"
#include "physics/bond_iact.h"

static double U_harm(const double xi[2], const double xj[2]) {
  return bond_harmonic_energy(1e6, 1e-4, hypot(xi[0] - xj[0], xi[1] - xj[1]));
}
static double U_nl(const double xi[2], const double xj[2]) {
  return bond_nonlinear_energy(1e-4, 2.5e-4, 4.5e-4, hypot(xi[0] - xj[0], xi[1] - xj[1]));
}

/* floor: the force at 1e-3 of the length scale, where differences of U lose digits */
static void check_fd(double (*U)(const double *, const double *), double fr_fn(double r),
                     const double xi[2], const double xj[2], double floor) {
  const double d[2] = {xi[0] - xj[0], xi[1] - xj[1]};
  const double fr = fr_fn(hypot(d[0], d[1]));
  const double h = 1e-9;
  for (int k = 0; k < 2; k++) {
    double p[2] = {xi[0], xi[1]}, q[2] = {xi[0], xi[1]};
    p[k] += h;
    q[k] -= h;
    const double fd = -(U(p, xj) - U(q, xj)) / (2 * h);
    const double scale = fabs(fr) * hypot(d[0], d[1]) + floor;
    if (!(fabs(fr * d[k] - fd) <= 1e-6 * scale))
      print_error("r = %g: F = %g, -dU/dx = %g\n", hypot(d[0], d[1]), fr * d[k], fd);
    assert_true(fabs(fr * d[k] - fd) <= 1e-6 * scale);
    /* and on j: F_j = -F_i */
    double pj[2] = {xj[0], xj[1]}, qj[2] = {xj[0], xj[1]};
    pj[k] += h;
    qj[k] -= h;
    const double fdj = -(U(xi, pj) - U(xi, qj)) / (2 * h);
    assert_true(fabs(-fr * d[k] - fdj) <= 1e-6 * scale);
  }
}

static double fr_harm(double r) {
  return bond_harmonic_iact(1e6, 1e-4, r);
}
static double fr_nl(double r) {
  return bond_nonlinear_iact(1e-4, 2.5e-4, 4.5e-4, r);
}

static void test_harmonic_gradient(void **state) {
  (void)state;
  const double xj[2] = {1e-3, 2e-3};
  for (double r = 0.5e-4; r <= 1.6e-4; r += 0.13e-4) {
    const double xi[2] = {xj[0] + 0.6 * r, xj[1] - 0.8 * r};
    check_fd(U_harm, fr_harm, xi, xj, 2e6 * 1e-7);
  }
}

static void test_nonlinear_gradient_and_stiffness(void **state) {
  (void)state;
  const double xj[2] = {1e-3, 2e-3}, r0 = 2.5e-4, L = 4.5e-4;
  for (double f = -0.97; f <= 0.97; f += 0.097) {
    const double r = r0 + f * L;
    if (r <= 0)
      continue;
    const double xi[2] = {xj[0] + 0.28 * r, xj[1] + 0.96 * r};
    check_fd(U_nl, fr_nl, xi, xj, 2e-4 / (L * L) * 4.5e-7);
    /* U'' by differences of U' = -fr r */
    const double h = 1e-10, up = -fr_nl(r + h) * (r + h), um = -fr_nl(r - h) * (r - h);
    const double k = bond_nonlinear_stiffness(1e-4, L, f * L);
    assert_true(fabs((up - um) / (2 * h) - k) <= 1e-5 * k);
  }
  /* SPEC: 2 k_b/r_max^2 at rest, about 60 times that at 0.8 r_max */
  const double k0 = bond_nonlinear_stiffness(1e-4, L, 0);
  assert_true(fabs(k0 - 2e-4 / (L * L)) < 1e-12 * k0);
  const double ratio = bond_nonlinear_stiffness(1e-4, L, 0.8 * L) / k0;
  assert_true(ratio > 55 && ratio < 65);
}

/* two solid particles bonded by a nonlinear bond, stretched to f r_max */
static PetscErrorCode stretched_pair(double f, PetscErrorCode *result) {
  const double zero[2] = {0, 0}, r0 = 2.5e-4, L = 4.5e-4;
  sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
  PetscFunctionBeginUser;
  OK(modules_enable(s, "bond_nonlinear", NULL));
  const double xa[2] = {4e-3, 5e-3}, xb[2] = {4e-3 + r0 + f * L, 5e-3};
  OK(particles_add_owned(&s->ps, 10, PTYPE_SOLID, xa, zero, 1e-5, 1000, NULL));
  OK(particles_add_owned(&s->ps, 11, PTYPE_SOLID, xb, zero, 1e-5, 1000, NULL));
  OK(topology_add_bond(s->topo, 10, 11, 0));
  for (int m = 0; m < s->n_modules; m++)
    OK(s->modules[m]->set_from_options(s->modules[m], s));
  OK(halo_create(&s->hal, 1e-3, PETSC_COMM_SELF));
  OK(s->modules[0]->setup(s->modules[0], s));
  OK(neighbours_rebuild(s));
  OK(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *result = sim_compute_forces(s);
  OK(PetscPopErrorHandler());
  if (!*result) {
    for (PetscInt i = 0; i < 2; i++)
      assert_true(isfinite(s->ps.a[i][0]) && isfinite(s->ps.a[i][1]));
  }
  fixture_destroy(&s);
  PetscFunctionReturn(0);
}

static void test_nonlinear_breaks_with_error(void **state) {
  PetscErrorCode r;
  (void)state;
  OK(stretched_pair(1.01, &r));
  assert_int_equal(r, PETSC_ERR_FP);
  OK(stretched_pair(1.0, &r)); /* exactly r_max: the limit itself */
  assert_int_equal(r, PETSC_ERR_FP);
  OK(stretched_pair(0.96, &r)); /* warns, runs */
  assert_int_equal(r, 0);
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_harmonic_gradient),
      cmocka_unit_test(test_nonlinear_gradient_and_stiffness),
      cmocka_unit_test(test_nonlinear_breaks_with_error),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(events_register());
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
