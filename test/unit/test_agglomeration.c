/* Clot agglomeration (src/physics/agglomeration.c; its bonds through bond_harmonic.c): the pairing
 * rules (mutual closest choice, at most one new bond per particle per event,
 * at most max_bonds per clot particle, probability P), the counter-based
 * random numbers (a pair's draw depends only on seed, event and the gid pair:
 * not on the order pairs are visited nor on how they are split over ranks),
 * and a new bond's zero energy and force at creation. */
#include "solid_fixture.h"
#include "dmhs/agglomeration.h"

#define assert_close(a, b, tol)                                                                    \
  do {                                                                                             \
    const double a_ = (a), b_ = (b), t_ = (tol);                                                   \
    if (!(fabs(a_ - b_) <= t_))                                                                    \
      fail_msg("%s = %.17g vs %s = %.17g: |diff| %.3e > %.3e", #a, a_, #b, b_, fabs(a_ - b_), t_); \
  } while (0)

static agglomeration_rules rules(double rmax, double P, PetscInt max_bonds) {
  agglomeration_rules r = {rmax, P, max_bonds, 7, 1, NULL};
  return r;
}

static agglomeration_point pt(PetscInt64 gid, double x, double y, PetscInt n_bonds) {
  agglomeration_point p = {gid, {x, y}, n_bonds};
  return p;
}

/* A at 0 and B at 3 on a line; candidates c1 at 1 and c2 at 1.2: both choose
 * A, A chooses c1, B chooses c2 but c2 did not choose B: one pair (A, c1). */
static void test_mutual_closest(void **state) {
  (void)state;
  const agglomeration_point clot[2] = {pt(10, 0, 0, 0), pt(20, 3, 0, 0)};
  const agglomeration_point cand[2] = {pt(1, 1, 0, 0), pt(2, 1.2, 0, 0)};
  const agglomeration_rules r = rules(10, 1, 4);
  PetscInt n, pairs[2][2];
  double r0[2];
  OK(agglomeration_pair(&r, clot, 2, cand, 2, &n, pairs, r0));
  assert_int_equal(n, 1);
  assert_int_equal(pairs[0][0], 0);
  assert_int_equal(pairs[0][1], 0);
  assert_close(r0[0], 1.0, 0);
  /* out of R_max: nothing */
  const agglomeration_rules near = rules(0.9, 1, 4);
  OK(agglomeration_pair(&near, clot, 2, cand, 2, &n, pairs, r0));
  assert_int_equal(n, 0);
}

/* A full clot particle is not chosen: c1 and c2 then both choose B, which
 * takes its closest (c2); one new bond per particle per event. */
static void test_max_bonds(void **state) {
  (void)state;
  const agglomeration_point clot[2] = {pt(10, 0, 0, 4), pt(20, 3, 0, 3)};
  const agglomeration_point cand[2] = {pt(1, 1, 0, 0), pt(2, 1.2, 0, 0)};
  const agglomeration_rules r = rules(10, 1, 4);
  PetscInt n, pairs[2][2];
  double r0[2];
  OK(agglomeration_pair(&r, clot, 2, cand, 2, &n, pairs, r0));
  assert_int_equal(n, 1);
  assert_int_equal(pairs[0][0], 1);
  assert_int_equal(pairs[0][1], 1);
  assert_close(r0[0], 1.8, 1e-15);
  const agglomeration_point full[2] = {pt(10, 0, 0, 4), pt(20, 3, 0, 4)};
  OK(agglomeration_pair(&r, full, 2, cand, 2, &n, pairs, r0));
  assert_int_equal(n, 0);
}

/* Many isolated pairs: with P = 0 none bonds, with P = 1 all, with P = 0.5
 * exactly those whose draw is below 0.5, about half of them. The result does
 * not depend on the order of the input (choices tie-break by gid). */
#define N_ISO 4000
static void test_probability_and_order(void **state) {
  (void)state;
  agglomeration_point *clot, *cand, *clot_r, *cand_r;
  PetscInt n, (*pairs)[2], (*pairs_r)[2];
  double *r0, *r0_r;
  OK(PetscMalloc4(N_ISO, &clot, N_ISO, &cand, N_ISO, &clot_r, N_ISO, &cand_r));
  OK(PetscMalloc4(N_ISO, &pairs, N_ISO, &pairs_r, N_ISO, &r0, N_ISO, &r0_r));
  for (PetscInt k = 0; k < N_ISO; k++) {
    clot[k] = pt(2 * k + 1, 10.0 * k, 0, 0);
    cand[k] = pt(2 * k + 2, 10.0 * k + 0.5 + 1e-4 * (k % 7), 0.1, 0);
  }
  agglomeration_rules r = rules(1, 0, 4);
  OK(agglomeration_pair(&r, clot, N_ISO, cand, N_ISO, &n, pairs, r0));
  assert_int_equal(n, 0);
  r.probability = 1;
  OK(agglomeration_pair(&r, clot, N_ISO, cand, N_ISO, &n, pairs, r0));
  assert_int_equal(n, N_ISO);
  r.probability = 0.5;
  OK(agglomeration_pair(&r, clot, N_ISO, cand, N_ISO, &n, pairs, r0));
  PetscInt expect = 0;
  for (PetscInt k = 0; k < N_ISO; k++)
    expect += agglomeration_uniform(7, 1, clot[k].gid, cand[k].gid) < 0.5;
  assert_int_equal(n, expect);
  assert_true(fabs(n / (double)N_ISO - 0.5) < 0.03);
  /* the same pairs from the input reversed */
  for (PetscInt k = 0; k < N_ISO; k++) {
    clot_r[k] = clot[N_ISO - 1 - k];
    cand_r[k] = cand[N_ISO - 1 - k];
  }
  PetscInt n_r;
  OK(agglomeration_pair(&r, clot_r, N_ISO, cand_r, N_ISO, &n_r, pairs_r, r0_r));
  assert_int_equal(n_r, n);
  for (PetscInt k = 0; k < n; k++) { /* reversed input: reversed pair list */
    const PetscInt q = n - 1 - k;
    assert_int_equal(clot[pairs[k][0]].gid, clot_r[pairs_r[q][0]].gid);
    assert_int_equal(cand[pairs[k][1]].gid, cand_r[pairs_r[q][1]].gid);
    assert_true(r0[k] == r0_r[q]);
  }
  /* another event draws anew */
  r.event = 2;
  PetscInt n2;
  OK(agglomeration_pair(&r, clot, N_ISO, cand, N_ISO, &n2, pairs_r, r0_r));
  PetscInt differ = 0;
  for (PetscInt k = 0; k < N_ISO; k++)
    differ += (agglomeration_uniform(7, 1, clot[k].gid, cand[k].gid) < 0.5) !=
              (agglomeration_uniform(7, 2, clot[k].gid, cand[k].gid) < 0.5);
  assert_true(differ > N_ISO / 3);
  OK(PetscFree4(clot, cand, clot_r, cand_r));
  OK(PetscFree4(pairs, pairs_r, r0, r0_r));
}

/* The draw of a pair is a function of (seed, event, gid pair) only:
 * symmetric in the pair, the same whichever order the pairs are visited in
 * and however they are split into "ranks", uniform in [0, 1). */
static void test_rng_independence(void **state) {
  (void)state;
  enum { N = 20000 };
  static double forward[N], backward[N], split[N];
  for (int k = 0; k < N; k++)
    forward[k] = agglomeration_uniform(42, 3, 5 * k, 5 * k + 17);
  for (int k = N - 1; k >= 0; k--)
    backward[k] = agglomeration_uniform(42, 3, 5 * k + 17, 5 * k);
  /* three "ranks" holding interleaved shares, each visiting its own pairs */
  for (int rank = 0; rank < 3; rank++)
    for (int k = rank; k < N; k += 3)
      split[k] = agglomeration_uniform(42, 3, 5 * k, 5 * k + 17);
  double mean = 0, var = 0;
  for (int k = 0; k < N; k++) {
    assert_true(forward[k] == backward[k]);
    assert_true(forward[k] == split[k]);
    assert_true(forward[k] >= 0 && forward[k] < 1);
    mean += forward[k];
  }
  mean /= N;
  for (int k = 0; k < N; k++)
    var += (forward[k] - mean) * (forward[k] - mean);
  var /= N;
  assert_close(mean, 0.5, 0.01);
  assert_close(var, 1.0 / 12, 0.005);
  /* seed and event matter */
  assert_true(agglomeration_hash(42, 3, 1, 2) != agglomeration_hash(43, 3, 1, 2));
  assert_true(agglomeration_hash(42, 3, 1, 2) != agglomeration_hash(42, 4, 1, 2));
  assert_true(agglomeration_hash(42, 3, 1, 2) != agglomeration_hash(42, 3, 1, 3));
}

/* Makes the pairing's bond between a clot particle at xa and a liquid one at
 * xb (its periodic image at xb + shift as a ghost when shift != 0) and
 * returns the bond's energy and the largest |a| right after its creation. */
static void new_bond(const double xa[2], const double xb[2], double shift, double *energy,
                     double *amax) {
  sim *s = fixture_create(1e-2, 1e-2, PETSC_TRUE);
  const double v0[2] = {0, 0};
  PetscInt ia, ib, ig;
  OK(particles_add_owned(&s->ps, 0, PTYPE_CLOT, xa, v0, 2.6e-4, 1056, &ia));
  OK(particles_add_owned(&s->ps, 1, PTYPE_FLUID, xb, v0, 2.6e-4, 1056, &ib));
  const agglomeration_point clot = pt(0, xa[0], xa[1], 0), cand = pt(1, xb[0], xb[1], 0);
  agglomeration_rules r = rules(5e-4, 1, 4);
  r.dom = &s->dom;
  PetscInt n, pairs[1][2];
  double r0;
  OK(agglomeration_pair(&r, &clot, 1, &cand, 1, &n, pairs, &r0));
  assert_int_equal(n, 1);
  static const int clot_module = 0; /* any address: the owner of the clot bond type */
  OK(topology_claim_bond_type(s->topo, AGGLOMERATION_BOND_TYPE, &clot_module));
  OK(topology_add_bond_r0(s->topo, 0, 1, AGGLOMERATION_BOND_TYPE, r0));
  s->ps.type[ib] = PTYPE_CLOT;
  if (shift != 0) { /* both ends' periodic images, as the halo makes them */
    const double xg[2] = {xb[0] + shift, xb[1]}, xh[2] = {xa[0] - shift, xa[1]};
    OK(particles_add_owned(&s->ps, 1, PTYPE_CLOT, xg, v0, 2.6e-4, 1056, &ig));
    OK(particles_add_owned(&s->ps, 0, PTYPE_CLOT, xh, v0, 2.6e-4, 1056, &ig));
    s->ps.n_owned = 2;
    s->ps.n_ghost = 2;
  }
  OK(topology_resolve(s->topo, &s->ps));
  assert_true(s->topo->n_bond_local >= 1);
  const PetscInt nr = s->ps.n_owned + s->ps.n_ghost;
  for (PetscInt i = 0; i < nr; i++)
    s->ps.a[i][0] = s->ps.a[i][1] = 0;
  double k[TOPOLOGY_MAX_TYPES];
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++)
    k[t] = 8000;
  const harmonic_bonds clots = {.owner = &clot_module, .k = k, .r0 = NULL};
  OK(bond_harmonic_forces(s, &clots));
  OK(bond_harmonic_energy_of(s, &clots, energy));
  *amax = 0;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    *amax = PetscMax(*amax, hypot(s->ps.a[i][0], s->ps.a[i][1]));
  s->ps.n_owned = nr;
  s->ps.n_ghost = 0;
  OK(topology_destroy(&s->topo));
  OK(cells_destroy(&s->cel));
  OK(particles_destroy(&s->ps));
  OK(PetscFree(s));
}

/* A bond made by the pairing, with its rest length, has zero energy and force
 * at creation: exactly inside the box; across the periodic seam the image's
 * rounding (x + L) leaves |r - r0| ~ 1 ulp of L, an energy ~ K (1e-18 m)^2. */
static void test_new_bond_zero_energy(void **state) {
  (void)state;
  double e, amax;
  const double xa[2] = {1.234567e-3, 5.4321e-3}, xb[2] = {1.4973e-3, 5.61e-3};
  new_bond(xa, xb, 0, &e, &amax);
  assert_true(e == 0.0);
  assert_true(amax == 0.0);
  const double ya[2] = {1.234567e-4, 5.4321e-3},
               yb[2] = {9.93e-3, 5.61e-3}; /* 3.2e-4 m apart through x = 0 */
  new_bond(ya, yb, -1e-2, &e, &amax);
  if (!(fabs(e) < 1e-28))
    print_error("periodic: energy %g, a %g\n", e, amax);
  assert_true(fabs(e) < 1e-28);
  assert_true(amax < 1e-9); /* vs K r0 / m ~ 1e4 m/s^2 for a bond stretched by r0 */
}

int main(int argc, char **argv) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mutual_closest),        cmocka_unit_test(test_max_bonds),
      cmocka_unit_test(test_probability_and_order), cmocka_unit_test(test_rng_independence),
      cmocka_unit_test(test_new_bond_zero_energy),
  };
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(events_register());
  const int failed = cmocka_run_group_tests(tests, NULL, NULL);
  PetscCall(PetscFinalize());
  return failed;
}
