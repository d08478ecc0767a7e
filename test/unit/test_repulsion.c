/* Repulsion: force = -grad U (finite differences) for (p1, p2) = (4, 2) and
 * (12, 6) across (0.5 r*, r*); zero at and beyond r*; repulsive inside; and the
 * module acts only between a fluid and a solid/wall particle, equal and opposite. */
#include "solid_fixture.h"
#include "physics/repulsion_iact.h"

static void test_repulsion_gradient(void **state) {
  (void)state;
  const int p[2][2] = {{4, 2}, {12, 6}};
  const double K = 4e-4, rs = 1e-4;
  for (int c = 0; c < 2; c++) {
    for (double f = 0.5; f < 1.0; f += 0.0437) {
      const double r = f * rs, h = 1e-6 * r;
      const double fr = repulsion_iact(K, rs, p[c][0], p[c][1], r * r);
      const double Fr = fr * r; /* radial force */
      const double fd = -(repulsion_energy(K, rs, p[c][0], p[c][1], r + h) -
                          repulsion_energy(K, rs, p[c][0], p[c][1], r - h)) /
                        (2 * h);
      assert_true(Fr > 0);
      assert_true(fabs(Fr - fd) <= 1e-6 * fabs(Fr));
    }
    assert_true(repulsion_energy(K, rs, p[c][0], p[c][1], rs) == 0);
    assert_true(fabs(repulsion_iact(K, rs, p[c][0], p[c][1], rs * rs)) < 1e-12 * K / rs);
  }
}

/* the row of a global id: a neighbour build re-sorts the rows by cell (cells_sort.c) */
static PetscInt row_of(const sim *s, PetscInt64 gid) {
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (s->ps.gid[i] == gid)
      return i;
  fail_msg("gid %" PetscInt64_FMT " not found", gid);
  return -1;
}

static void test_repulsion_module(void **state) {
  (void)state;
  const double zero[2] = {0, 0};
  sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
  module *m;
  OK(modules_enable(s, "repulsion", &m));
  const double xs[2] = {5e-3, 5e-3}, xf[2] = {5e-3 + 0.6e-4, 5e-3 + 0.3e-4},
               xf2[2] = {5e-3 - 0.5e-4, 5e-3};
  OK(particles_add_owned(&s->ps, 0, PTYPE_SOLID, xs, zero, 2e-5, 1000, NULL));
  OK(particles_add_owned(&s->ps, 1, PTYPE_FLUID, xf, zero, 1e-5, 1000, NULL));
  OK(particles_add_owned(&s->ps, 2, PTYPE_FLUID, xf2, zero, 1e-5, 1000,
                         NULL)); /* fluid-fluid with 1: no force */
  fixture_setup(s);
  double P[2] = {0, 0};
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 2; k++)
      P[k] += s->ps.mass[i] * s->ps.a[i][k];
  const PetscInt r1 = row_of(s, 1), r2 = row_of(s, 2);
  const double F1 = s->ps.mass[r1] * hypot(s->ps.a[r1][0], s->ps.a[r1][1]);
  assert_true(F1 > 0);
  assert_true(fabs(P[0]) < 1e-14 * F1 && fabs(P[1]) < 1e-14 * F1);
  /* the fluid particle is pushed away from the solid */
  assert_true(s->ps.a[r1][0] > 0 && s->ps.a[r1][1] > 0 && s->ps.a[r2][0] < 0);
  double e;
  OK(m->energy(m, s, &e));
  const double expect = repulsion_energy(4e-4, 1e-4, 4, 2, hypot(0.6e-4, 0.3e-4)) +
                        repulsion_energy(4e-4, 1e-4, 4, 2, 0.5e-4);
  assert_true(fabs(e - expect) < 1e-12 * expect);
  fixture_destroy(&s);
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_repulsion_gradient),
      cmocka_unit_test(test_repulsion_module),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(events_register());
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
