/* Topology: any particle type as a bond end, bond types owned by modules; bonds by gid
 * resolved across a periodic boundary (nearest image,
 * force on both owned ends, energy counted once); bonded 1-2 and 1-3 pairs
 * left out of the pair list unless -special_bonds_include; an isolated
 * bonded structure under velocity Verlet conserves energy (bounded drift
 * over 1e5 steps) and momentum to round-off, for both bond styles. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include "solid_fixture.h"
#include "dmhs/solid_load.h"
#include "scenes/solid_strip.h"

static void test_periodic_bond(void **state) {
  (void)state;
  const double zero[2] = {0, 0}, L = 1e-3, K = 1e6, r0 = 1.2e-4, m = 2e-5;
  sim *s = fixture_create(L, L, PETSC_TRUE);
  OK(modules_enable(s, "bond_harmonic", NULL));
  OK(modules_enable(s, "angle_harmonic", NULL));
  OK(bond_set_default(s, K, r0, 0));
  const double xa[2] = {0.05e-3, 0.5e-3}, xb[2] = {L - 0.05e-3, 0.5e-3},
               xc[2] = {L - 0.05e-3, 0.6e-3};
  OK(particles_add_owned(&s->ps, 7, PTYPE_SOLID, xa, zero, m, 1000, NULL));
  OK(particles_add_owned(&s->ps, 3, PTYPE_SOLID, xb, zero, m, 1000, NULL));
  OK(particles_add_owned(&s->ps, 5, PTYPE_SOLID, xc, zero, m, 1000, NULL));
  OK(topology_add_bond(s->topo, 7, 3, 0));
  OK(topology_add_angle(s->topo, 7, 3, 5,
                        0)); /* right angle at 3 across the boundary: no angle force */
  fixture_setup(s);
  assert_true(s->ps.n_ghost > 0);
  /* r = 1e-4 < r0: 7 is pushed to +x, 3 to -x, by 2 K (r0 - r) */
  const double F = 2 * K * (r0 - 1e-4);
  assert_true(fabs(s->ps.a[0][0] * m - F) < 1e-9 * F);
  assert_true(fabs(s->ps.a[1][0] * m + F) < 1e-9 * F);
  assert_true(fabs(s->ps.a[0][1]) < 1e-9 * F / m && fabs(s->ps.a[1][1]) < 1e-9 * F / m);
  assert_true(fabs(s->ps.a[2][0]) < 1e-9 * F / m && fabs(s->ps.a[2][1]) < 1e-9 * F / m);
  double e;
  OK(s->modules[0]->energy(s->modules[0], s, &e));
  assert_true(fabs(e - K * (r0 - 1e-4) * (r0 - 1e-4)) < 1e-9 * e);
  /* a partner that is not there is an error naming both gids */
  OK(topology_add_bond(s->topo, 7, 99, 0));
  OK(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  const PetscErrorCode r = neighbours_rebuild(s);
  OK(PetscPopErrorHandler());
  assert_int_equal(r, PETSC_ERR_PLIB);
  fixture_destroy(&s);
}

static PetscInt count_pairs_between_solids(sim *s) {
  PetscInt n = 0;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++)
    n += s->ps.type[s->cel.pair_i[k]] == PTYPE_SOLID && s->ps.type[s->cel.pair_j[k]] == PTYPE_SOLID;
  return n;
}

static void build_strip_root(sim *s, PetscInt n, double r0, double m, PetscInt n_clamp,
                             PetscBool hinged) {
  solid_strip st = {.n = n,
                    .n_clamp = n_clamp,
                    .hinged = hinged,
                    .origin = {4e-3, 5e-3},
                    .along = {1, 0},
                    .across = {0, 1},
                    .spacing = r0,
                    .mass = m,
                    .rho = 1000};
  PetscInt64 gid = 100;
  OK(solid_strip_build(s, &st, &gid));
}

static void build_strip(sim *s, PetscInt n, double r0, double m, PetscInt n_clamp) {
  build_strip_root(s, n, r0, m, n_clamp, PETSC_FALSE);
}

/* A strip turned as a whole about column 0's layer-0 particle: a hinged root
 * takes no moment (no force anywhere), a clamped one resists (its fixed
 * layer-1 particle pulls back) */
static void test_hinged_root(void **state) {
  (void)state;
  const double r0 = 1e-4, m = 2e-5, phi = 0.2, K = 1e6;
  for (int hinged = 0; hinged < 2; hinged++) {
    sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
    OK(modules_enable(s, "bond_harmonic", NULL));
    OK(modules_enable(s, "angle_harmonic", NULL));
    OK(bond_set_default(s, K, r0, 0));
    OK(angle_set_default(s, 0.01, 90.0));
    build_strip_root(s, 5, r0, m, 1, hinged ? PETSC_TRUE : PETSC_FALSE);
    PetscInt n_wall = 0;
    for (PetscInt i = 0; i < s->ps.n_owned; i++) {
      if (s->ps.type[i] == PTYPE_WALL) { /* the pivot, and the clamp's layer-1 particle */
        n_wall++;
        continue;
      }
      const double dx = s->ps.x[i][0] - 4e-3, dy = s->ps.x[i][1] - 5e-3;
      s->ps.x[i][0] = 4e-3 + cos(phi) * dx - sin(phi) * dy;
      s->ps.x[i][1] = 5e-3 + sin(phi) * dx + cos(phi) * dy;
    }
    assert_int_equal(n_wall, hinged ? 1 : 2);
    fixture_setup(s);
    double a_max = 0;
    for (PetscInt i = 0; i < s->ps.n_owned; i++)
      if (s->ps.type[i] == PTYPE_SOLID)
        a_max = PetscMax(a_max, hypot(s->ps.a[i][0], s->ps.a[i][1]));
    const double a_scale = 2 * K * r0 * phi / m; /* a bond stretched by r0 phi */
    if (hinged)
      assert_true(a_max < 1e-9 * a_scale);
    else
      assert_true(a_max > 0.1 * a_scale);
    fixture_destroy(&s);
  }
}

static void test_exclusions(void **state) {
  (void)state;
  for (int include = 0; include < 2; include++) {
    sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
    module *rep;
    OK(modules_enable(s, "bond_harmonic", NULL));
    OK(modules_enable(s, "angle_harmonic", NULL));
    OK(modules_enable(s, "repulsion", &rep));
    OK(repulsion_set_default(rep, 4e-4, 1.5e-4, 4, 2)); /* cutoff 1.5 r0: sides and diagonals */
    s->topo->special_include = include ? PETSC_TRUE : PETSC_FALSE;
    build_strip(s, 3, 1e-4, 2e-5, 0);
    fixture_setup(s);
    /* 2 x 3 lattice: 7 bonds (sides) + 4 diagonals within 1.5 r0; the diagonals
     * are the 1-3 partners of the corner angles */
    assert_int_equal(count_pairs_between_solids(s), include ? 11 : 0);
    fixture_destroy(&s);
  }
}

/* substeps > 1: the same structure on substeps sub-steps of dt/substeps
 * (src/core/substep.c), with the same sub-step as the plain run's step */
static void conservation(const char *bond_module, double k, double rmax, double ka,
                         PetscInt substeps) {
  const PetscInt n = 4;
  const double r0 = 1e-4, m = 2e-5;
  sim *s = fixture_create(1e-2, 1e-2, PETSC_FALSE);
  fixture_substeps(s, substeps);
  OK(modules_enable(s, bond_module, NULL));
  OK(modules_enable(s, "angle_harmonic", NULL));
  OK(bond_set_default(s, k, r0, rmax));
  OK(angle_set_default(s, ka, 90));
  build_strip(s, n, r0, m, 0);
  /* perturb positions and give velocities: a vibrating, drifting, spinning structure */
  unsigned long long seed = 12345;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    for (int c = 0; c < 2; c++) {
      s->ps.x[i][c] += 0.05 * r0 * fixture_rand(&seed);
      s->ps.v[i][c] = 0.02 + 0.05 * fixture_rand(&seed);
    }
  fixture_setup(s);
  double P0[2], P[2];
  const double E0 = fixture_energy(s, P0);
  /* the fastest mode: a particle on 3 bonds and 4 angles; dt well inside the limit */
  const double kbond = strcmp(bond_module, "bond_harmonic") ? 2 * k / (rmax * rmax) : 2 * k;
  const double kmax = PetscMax(kbond, 2 * ka / (r0 * r0));
  s->dt = 0.02 * sqrt(m / kmax) * (double)substeps;
  double drift = 0, pscale = 0, t[100], e[100];
  int n_samples = 0;
  double dP = 0, impulse = 0; /* round-off scale: eps x the impulses summed over the run */
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    pscale += m * hypot(s->ps.v[i][0], s->ps.v[i][1]);
  const int n_steps = 100000 / (int)substeps;
  for (int step = 1; step <= n_steps; step++) {
    fixture_step(s);
    for (PetscInt i = 0; i < s->ps.n_owned; i++)
      impulse += m * s->dt * hypot(s->ps.a[i][0], s->ps.a[i][1]);
    if (step % (1000 / (int)substeps) == 0) {
      const double E = fixture_energy(s, P);
      drift = PetscMax(drift, fabs(E - E0) / E0);
      t[n_samples] = s->t;
      e[n_samples++] = E / E0 - 1;
      dP = PetscMax(dP, PetscMax(fabs(P[0] - P0[0]), fabs(P[1] - P0[1])));
    }
  }
  /* secular drift: slope of a least-squares line through E(t) over the run */
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_set_error_handler_off();
  assert_int_equal(
      gsl_fit_linear(t, 1, e, 1, (size_t)n_samples, &c0, &c1, &cov00, &cov01, &cov11, &sumsq), 0);
  const double secular = fabs(c1 * s->t);
  print_message(
      "%s, %d sub-steps: over 1e5 sub-steps (dt/substeps = %.3g s = 0.02 sqrt(m/k_max)): max |E - "
      "E0|/E0 = %.3e, fitted drift %.3e\n",
      bond_module, (int)substeps, s->dt / (double)substeps, drift, secular);
  print_message("  momentum change %.3e kg m/s; eps x summed impulses %.3e; sum m|v0| %.3e\n", dP,
                DBL_EPSILON * impulse, pscale);
  assert_true(dP < DBL_EPSILON * impulse);
  assert_true(drift < 2e-3); /* Verlet: bounded O((omega dt)^2) oscillation */
  assert_true(secular < 5e-5);
  fixture_destroy(&s);
}

/* Any particle type may be a bond end: a liquid-solid bond gets its force and its pair
 * leaves the pair list; a bond type claimed by another module is left to that module
 * (the bond module computes no force for it), and a type claimed twice is an error. */
static void test_any_type_and_owners(void **state) {
  (void)state;
  const double zero[2] = {0, 0}, K = 1e6, r0 = 1.2e-4, m = 2e-5;
  sim *s = fixture_create(1e-3, 1e-3, PETSC_FALSE);
  module *rep;
  OK(modules_enable(s, "bond_harmonic", NULL));
  OK(modules_enable(s, "repulsion", &rep));
  OK(repulsion_set_default(rep, 4e-4, 1.5e-4, 4, 2));
  OK(bond_set_default(s, K, r0, 0));
  const double xa[2] = {0.4e-3, 0.5e-3}, xb[2] = {0.5e-3, 0.5e-3}, xc[2] = {0.6e-3, 0.5e-3};
  OK(particles_add_owned(&s->ps, 0, PTYPE_FLUID, xa, zero, m, 1000, NULL));
  OK(particles_add_owned(&s->ps, 1, PTYPE_SOLID, xb, zero, m, 1000, NULL));
  OK(particles_add_owned(&s->ps, 2, PTYPE_SOLID, xc, zero, m, 1000, NULL));
  OK(topology_add_bond(s->topo, 0, 1, 0)); /* liquid - solid */
  static const int other_module = 0;       /* stands for a clot-like module */
  OK(topology_claim_bond_type(s->topo, 3, &other_module));
  OK(topology_add_bond(s->topo, 1, 2, 3)); /* its type: no force from bond_harmonic */
  fixture_setup(s);
  const double F = 2 * K * (r0 - 1e-4); /* pushes 0 to -x, 1 to +x */
  assert_true(fabs(s->ps.a[0][0] * m + F) < 1e-9 * F);
  assert_true(fabs(s->ps.a[2][0]) < 1e-9 * F / m); /* only repulsion could act, and 1-2 are
                                                       bonded: excluded */
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt64 gi = s->ps.gid[s->cel.pair_i[k]], gj = s->ps.gid[s->cel.pair_j[k]];
    assert_false((gi == 0 && gj == 1) || (gi == 1 && gj == 0));
    assert_false((gi == 1 && gj == 2) || (gi == 2 && gj == 1));
  }
  /* a second module claiming the type: refused */
  static const int third = 0;
  OK(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  const PetscErrorCode r = topology_claim_bond_type(s->topo, 3, &third);
  OK(PetscPopErrorHandler());
  assert_int_equal(r, PETSC_ERR_ARG_INCOMP);
  fixture_destroy(&s);
}

static void test_conservation_harmonic(void **state) {
  (void)state;
  conservation("bond_harmonic", 1e6, 0, 0.01, 1);
}

static void test_conservation_nonlinear(void **state) {
  (void)state;
  conservation("bond_nonlinear", 1e-4, 0.5e-4, 1e-4, 1);
}

/* an isolated structure on 4 sub-steps per step conserves energy and
 * momentum as well as on one (it sees no other force: a_hold = 0) */
static void test_conservation_substeps(void **state) {
  (void)state;
  conservation("bond_harmonic", 1e6, 0, 0.01, 4);
  conservation("bond_nonlinear", 1e-4, 0.5e-4, 1e-4, 4);
  fields_reset();
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_periodic_bond),         cmocka_unit_test(test_exclusions),
      cmocka_unit_test(test_conservation_harmonic), cmocka_unit_test(test_conservation_nonlinear),
      cmocka_unit_test(test_conservation_substeps), cmocka_unit_test(test_any_type_and_owners),
      cmocka_unit_test(test_hinged_root),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(events_register());
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
