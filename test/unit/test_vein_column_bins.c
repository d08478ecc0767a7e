/* The vein crossing check's nearest-column search (src/scenes/vein/vein_column_bins.c). Proves, for
 * a leaflet of 120 columns bent through a quarter circle (and one straight leaflet), that for
 * thousands of random points inside the leaflet's box the binned search returns what a search
 * over every column returns: the column with the nearest mid-point, the lowest on a tie, and
 * -1 exactly when no mid-point is within sqrt(10) dx; also for a leaflet that straddles the
 * periodic boundary in x (mid-points and points taken by the minimum image), and after a
 * rebuild for a leaflet that moved and grew (the arrays are reused). */
#include <string.h>
#include "unit_common.h"
#include "dmhs/domain.h"
#include "scenes/vein/vein_column_bins.h"

#define NC 120
#define DX 1e-4

static const domain box_x_periodic = {
    .lo = {0.0, 0.0}, .hi = {0.02, 0.01}, .periodic = {PETSC_TRUE, PETSC_FALSE}};

/* Leaflet 0: NC columns of two layers dx apart, along a quarter circle of radius R about
 * (cx, cy) (bent = 1) or along a straight line at 30 degrees (bent = 0); positions wrapped
 * into the domain. */
static void make_leaflet(vein_leaflets *v, double cx, double cy, int bent, PetscInt nc) {
  memset(&v->lay, 0, sizeof(v->lay));
  v->lay.dx = DX;
  v->lay.leaflet[0].n_columns = nc;
  v->lay.leaflet[1].n_columns = 1;
  v->n_leaf[0] = 2 * nc;
  v->n_leaf[1] = 2;
  const double R = nc * DX / (0.5 * PETSC_PI);
  for (PetscInt c = 0; c < nc; c++) {
    const double s = (double)c / (double)(nc - 1);
    double p[2], n[2];
    if (bent) {
      const double phi = 0.5 * PETSC_PI * s;
      p[0] = cx + R * cos(phi);
      p[1] = cy + R * sin(phi);
      n[0] = cos(phi);
      n[1] = sin(phi);
    } else {
      p[0] = cx + s * nc * DX * cos(PETSC_PI / 6);
      p[1] = cy + s * nc * DX * sin(PETSC_PI / 6);
      n[0] = -sin(PETSC_PI / 6);
      n[1] = cos(PETSC_PI / 6);
    }
    for (int l = 0; l < 2; l++) {
      double q[2] = {p[0] + (l - 0.5) * DX * n[0], p[1] + (l - 0.5) * DX * n[1]};
      domain_wrap(&box_x_periodic, q);
      v->x[2 * c + l][0] = q[0];
      v->x[2 * c + l][1] = q[1];
    }
  }
  v->x[2 * nc][0] = v->x[2 * nc + 1][0] = 0.5; /* leaflet 1: one column, unused */
  v->x[2 * nc][1] = v->x[2 * nc + 1][1] = 0.5;
}

/* The leaflet's box as the crossing check makes it: centre and half-widths 4 dx beyond its
 * particles, positions taken relative to the first particle by the minimum image. */
static void leaflet_box(const vein_leaflets *v, double box[4]) {
  double lo[2] = {0, 0}, hi[2] = {0, 0};
  for (PetscInt k = 1; k < v->n_leaf[0]; k++) {
    double d[2] = {v->x[k][0] - v->x[0][0], v->x[k][1] - v->x[0][1]};
    domain_min_image(&box_x_periodic, d);
    for (int e = 0; e < 2; e++) {
      lo[e] = PetscMin(lo[e], d[e]);
      hi[e] = PetscMax(hi[e], d[e]);
    }
  }
  for (int e = 0; e < 2; e++) {
    box[e] = v->x[0][e] + 0.5 * (lo[e] + hi[e]);
    box[2 + e] = 0.5 * (hi[e] - lo[e]) + 4 * DX;
  }
}

/* Every column, in order: the reference the binned search must reproduce. */
static PetscInt nearest_by_all(const vein_leaflets *v, const double box[4], const double d[2]) {
  double best = 10.0 * DX * DX;
  PetscInt cb = -1;
  for (PetscInt c = 0; c < v->lay.leaflet[0].n_columns; c++) {
    double m[2];
    vein_leaflets_column_mid(v, 0, c, m);
    m[0] -= box[0];
    m[1] -= box[1];
    domain_min_image(&box_x_periodic, m);
    const double e0 = d[0] - m[0], e1 = d[1] - m[1], r2 = e0 * e0 + e1 * e1;
    if (r2 < best) {
      best = r2;
      cb = c;
    }
  }
  return cb;
}

/* Random points in the box, half of them within 3 dx of a random column's mid-point (where
 * the answer is a column), the others anywhere (mostly -1). */
static void check_against_all(const vein_leaflets *v, column_bins *b, unsigned seed) {
  double box[4];
  leaflet_box(v, box);
  OK(column_bins_build(b, v, &box_x_periodic, 0, box));
  unit_rng g = {seed};
  int found = 0, none = 0;
  for (int t = 0; t < 4000; t++) {
    double d[2];
    if (t % 2) {
      const PetscInt c = (PetscInt)(unit_uniform(&g) * v->lay.leaflet[0].n_columns);
      double m[2];
      vein_leaflets_column_mid(v, 0, PetscMin(c, v->lay.leaflet[0].n_columns - 1), m);
      d[0] = m[0] - box[0] + unit_range(&g, -3 * DX, 3 * DX);
      d[1] = m[1] - box[1] + unit_range(&g, -3 * DX, 3 * DX);
      domain_min_image(&box_x_periodic, d);
    } else {
      d[0] = unit_range(&g, -box[2], box[2]);
      d[1] = unit_range(&g, -box[3], box[3]);
    }
    if (fabs(d[0]) > box[2] || fabs(d[1]) > box[3])
      continue; /* the check asks only for points inside the box */
    const PetscInt want = nearest_by_all(v, box, d), got = column_bins_nearest(b, d, DX);
    if (want != got)
      fail_msg("point (%g, %g) from the box centre: binned search %d, every column %d", d[0], d[1],
               (int)got, (int)want);
    found += want >= 0;
    none += want < 0;
  }
  assert_true(found > 1000); /* both answers were exercised */
  assert_true(none > 100);
}

static void test_nearest_matches_every_column(void **state) {
  (void)state;
  vein_leaflets v = {0};
  column_bins b = {0};
  OK(PetscMalloc1(2 * NC + 2, &v.x));
  make_leaflet(&v, 0.008, 0.002, 1, NC); /* bent, inside the domain */
  check_against_all(&v, &b, 1u);
  make_leaflet(&v, 0.004, 0.003, 0, NC); /* straight; the arrays are reused */
  check_against_all(&v, &b, 2u);
  make_leaflet(&v, 0.0195, 0.002, 1, NC); /* across the periodic boundary in x */
  check_against_all(&v, &b, 3u);
  make_leaflet(&v, 0.001, 0.002, 1, NC / 2); /* fewer columns, a smaller box */
  check_against_all(&v, &b, 4u);
  OK(column_bins_destroy(&b));
  OK(PetscFree(v.x));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_nearest_matches_every_column),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
