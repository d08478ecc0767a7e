/* Module agglomeration: clots grown by bonds made at run time (the
 * rules in include/dmhs/agglomeration.h and doc/theory.md "Clot
 * agglomeration"). Enabled by a scene (the vein with -vein_clots); a run
 * without it allocates nothing of this.
 *
 * Determinism: an event is collective. Every rank gathers the clot particles
 * and the candidates (MPI_Allgatherv), sorts them by gid and takes the same
 * decisions; the rank owning a bond's clot end gives it to the collective
 * topology_add_bonds, which numbers the bonds by their gids; the random draw of a
 * pair is a hash of (seed, event, gid pair). The clots are then the same on any
 * rank count and across a restart (the clot membership is checkpointed here, the
 * bonds with the topology, the particle types with the particles).
 *
 * clots.csv (rank 0, through csv.h): step,t,clot_particles,clot_bonds,clot_1..clot_n,
 * one row at the seeding and at every event; clot_k counts the particles of seed k's
 * clot. A restart keeps its rows up to the checkpoint's step. */
#include <math.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/agglomeration.h"
#include "dmhs/bond.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "dmhs/gather.h"

#define AGG_CSV "clots.csv"

/* ---- counter-based random numbers ---------------------------------------- */

static inline uint64_t splitmix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

uint64_t agglomeration_hash(uint64_t seed, uint64_t event, PetscInt64 ga, PetscInt64 gb) {
  const uint64_t lo = (uint64_t)PetscMin(ga, gb), hi = (uint64_t)PetscMax(ga, gb);
  uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ event);
  h = splitmix64(h ^ lo);
  return splitmix64(h ^ hi);
}

double agglomeration_uniform(uint64_t seed, uint64_t event, PetscInt64 ga, PetscInt64 gb) {
  return (double)(agglomeration_hash(seed, event, ga, gb) >> 11) * 0x1.0p-53;
}

/* ---- pairing (pure) ------------------------------------------------------- */

static double agg_dist(const agglomeration_rules *r, const double a[DMHS_DIM],
                       const double b[DMHS_DIM]) {
  double d[DMHS_DIM] = {a[0] - b[0], a[1] - b[1]};
  if (r->dom)
    domain_min_image(r->dom, d);
  return sqrt(d[0] * d[0] + d[1] * d[1]);
}

PetscErrorCode agglomeration_pair(const agglomeration_rules *r, const agglomeration_point *clot,
                                  PetscInt n_clot, const agglomeration_point *cand, PetscInt n_cand,
                                  PetscInt *n_pairs, PetscInt (*pairs)[2], double *r0) {
  PetscInt *best_of_cand, *best_of_clot;
  PetscFunctionBeginUser;
  *n_pairs = 0;
  if (!n_clot || !n_cand)
    PetscFunctionReturn(0);
  PetscCall(PetscMalloc2(n_cand, &best_of_cand, n_clot, &best_of_clot));
  /* each candidate's closest open clot particle (ties: lower gid) */
  for (PetscInt c = 0; c < n_cand; c++) {
    double bd = INFINITY;
    best_of_cand[c] = -1;
    for (PetscInt p = 0; p < n_clot; p++) {
      if (clot[p].n_bonds >= r->max_bonds)
        continue;
      const double d = agg_dist(r, cand[c].x, clot[p].x);
      if (d >= r->rmax)
        continue;
      if (d < bd || (d == bd && clot[p].gid < clot[best_of_cand[c]].gid)) {
        bd = d;
        best_of_cand[c] = p;
      }
    }
  }
  /* each open clot particle's closest candidate */
  for (PetscInt p = 0; p < n_clot; p++) {
    double bd = INFINITY;
    best_of_clot[p] = -1;
    if (clot[p].n_bonds >= r->max_bonds)
      continue;
    for (PetscInt c = 0; c < n_cand; c++) {
      const double d = agg_dist(r, cand[c].x, clot[p].x);
      if (d >= r->rmax)
        continue;
      if (d < bd || (d == bd && cand[c].gid < cand[best_of_clot[p]].gid)) {
        bd = d;
        best_of_clot[p] = c;
      }
    }
  }
  /* mutual choices, each kept with probability P: one bond per particle */
  for (PetscInt p = 0; p < n_clot; p++) {
    const PetscInt c = best_of_clot[p];
    if (c < 0 || best_of_cand[c] != p)
      continue;
    if (agglomeration_uniform(r->seed, r->event, clot[p].gid, cand[c].gid) >= r->probability)
      continue;
    pairs[*n_pairs][0] = p;
    pairs[*n_pairs][1] = c;
    r0[*n_pairs] = agg_dist(r, cand[c].x, clot[p].x);
    (*n_pairs)++;
  }
  PetscCall(PetscFree2(best_of_cand, best_of_clot));
  PetscFunctionReturn(0);
}

/* ---- the module ---------------------------------------------------------- */

typedef struct {
  /* options */
  double interval, start, rmax, probability, bond_k;
  PetscInt max_bonds;
  PetscInt rng_seed;
  PetscInt n_points;
  double points[2 * AGGLOMERATION_MAX_SEEDS];
  PetscBool start_set, k_set;
  agglomeration_seed_fn chooser;
  void *chooser_ctx;
  double m_min; /* smallest liquid mass [kg] */
  /* replicated state (checkpointed) */
  PetscInt64 next_event; /* 0: the seeding is due; k >= 1: event k */
  PetscInt n_seeds;
  PetscInt64 seed_gid[AGGLOMERATION_MAX_SEEDS];
  PetscInt n_clot, n_alloc;
  PetscInt64 *clot_gid;  /* sorted */
  PetscInt *clot_seed;   /* seed index of each clot particle's clot */
  PetscInt restart_step; /* the checkpoint's step (0: a fresh run) */
  FILE *csv;             /* clots.csv, rank 0 */
} agg_data;

static int cmp_gid(const void *a, const void *b) {
  const PetscInt64 x = *(const PetscInt64 *)a, y = *(const PetscInt64 *)b;
  return (x > y) - (x < y);
}

static PetscInt agg_clot_index(const agg_data *d, PetscInt64 gid) {
  PetscInt lo = 0, hi = d->n_clot;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (d->clot_gid[mid] < gid)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < d->n_clot && d->clot_gid[lo] == gid ? lo : -1;
}

/* Adds n (gid, seed) members and keeps the list sorted by gid. */
static PetscErrorCode agg_add_members(agg_data *d, PetscInt n, const PetscInt64 *gid,
                                      const PetscInt *seed) {
  PetscFunctionBeginUser;
  if (d->n_clot + n > d->n_alloc) {
    const PetscInt grown = PetscMax(2 * d->n_alloc, d->n_clot + n + 64);
    PetscInt64 *g;
    PetscInt *sd;
    PetscCall(PetscMalloc2(grown, &g, grown, &sd));
    if (d->n_clot) {
      PetscCall(PetscArraycpy(g, d->clot_gid, d->n_clot));
      PetscCall(PetscArraycpy(sd, d->clot_seed, d->n_clot));
    }
    PetscCall(PetscFree2(d->clot_gid, d->clot_seed));
    d->clot_gid = g;
    d->clot_seed = sd;
    d->n_alloc = grown;
  }
  for (PetscInt k = 0; k < n; k++) {
    /* insertion keeps the order (n is small per event) */
    PetscInt at = d->n_clot;
    while (at > 0 && d->clot_gid[at - 1] > gid[k]) {
      d->clot_gid[at] = d->clot_gid[at - 1];
      d->clot_seed[at] = d->clot_seed[at - 1];
      at--;
    }
    PetscCheck(at == 0 || d->clot_gid[at - 1] != gid[k], PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "agglomeration: particle gid %" PetscInt64_FMT " joined a clot twice", gid[k]);
    d->clot_gid[at] = gid[k];
    d->clot_seed[at] = seed[k];
    d->n_clot++;
  }
  PetscFunctionReturn(0);
}

/* Owned rows whose gid is in the sorted list become clot particles. */
static void agg_mark_owned(sim *s, PetscInt n, const PetscInt64 *sorted) {
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (bsearch(&s->ps.gid[i], sorted, (size_t)n, sizeof(PetscInt64), cmp_gid))
      s->ps.type[i] = PTYPE_CLOT;
}

static int cmp_point(const void *a, const void *b) {
  const PetscInt64 x = ((const agglomeration_point *)a)->gid,
                   y = ((const agglomeration_point *)b)->gid;
  return (x > y) - (x < y);
}

/* Every rank's points, on every rank, sorted by gid. */
static PetscErrorCode agg_allgather(sim *s, const agglomeration_point *mine, PetscInt n_mine,
                                    agglomeration_point **all, PetscInt *n_all) {
  size_t n = 0;
  PetscFunctionBeginUser;
  *n_all = 0;
  PetscCall(gather_all(s->comm, "agglomeration points", mine, (size_t)n_mine,
                       sizeof(agglomeration_point), all, &n, NULL));
  *n_all = (PetscInt)n;
  qsort(*all, n, sizeof(agglomeration_point), cmp_point);
  PetscFunctionReturn(0);
}

/* The liquid particle nearest to each -agglomeration_seeds point (ties: lower gid). */
static PetscErrorCode agg_seeds_from_points(sim *s, agg_data *d, PetscInt *n, PetscInt64 gids[]) {
  PetscFunctionBeginUser;
  *n = d->n_points / 2;
  for (PetscInt k = 0; k < *n; k++) {
    agglomeration_point mine = {-1, {INFINITY, 0}, 0}, *all;
    PetscInt n_all;
    for (PetscInt i = 0; i < s->ps.n_owned; i++) {
      if (s->ps.type[i] != PTYPE_FLUID)
        continue;
      double dd[2] = {s->ps.x[i][0] - d->points[2 * k], s->ps.x[i][1] - d->points[2 * k + 1]};
      domain_min_image(&s->dom, dd);
      const double d2 = dd[0] * dd[0] + dd[1] * dd[1];
      if (d2 < mine.x[0] || (d2 == mine.x[0] && s->ps.gid[i] < mine.gid)) {
        mine.x[0] = d2;
        mine.gid = s->ps.gid[i];
      }
    }
    PetscCall(agg_allgather(s, &mine, 1, &all, &n_all));
    PetscInt best = -1;
    for (PetscInt r = 0; r < n_all; r++)
      if (all[r].gid >= 0 && (best < 0 || all[r].x[0] < all[best].x[0]))
        best = r; /* sorted: ties keep the lower gid */
    PetscCheck(best >= 0, s->comm, PETSC_ERR_ARG_WRONG,
               "-agglomeration_seeds: no liquid particle left for point %g,%g", d->points[2 * k],
               d->points[2 * k + 1]);
    gids[k] = all[best].gid;
    PetscCall(PetscFree(all));
  }
  PetscFunctionReturn(0);
}

/* clots.csv through csv.h: the first row opens it, after a restart keeping the rows up to
 * the checkpoint's step (its first column is the step). */
static PetscErrorCode agg_write_row(sim *s, agg_data *d) {
  char line[128 + 24 * AGGLOMERATION_MAX_SEEDS];
  size_t n = 0;
  PetscFunctionBeginUser;
  if (s->rank != 0)
    PetscFunctionReturn(0);
  if (!d->csv) {
    n = (size_t)snprintf(line, sizeof(line), "step,t,clot_particles,clot_bonds");
    for (PetscInt k = 0; k < d->n_seeds; k++)
      n += (size_t)snprintf(line + n, sizeof(line) - n, ",clot_%" PetscInt_FMT, k + 1);
    snprintf(line + n, sizeof(line) - n, "\n");
    PetscCall(csv_open_keeping(s, AGG_CSV, line, (double)d->restart_step + 0.5, &d->csv));
  }
  PetscInt count[AGGLOMERATION_MAX_SEEDS] = {0};
  for (PetscInt k = 0; k < d->n_clot; k++)
    count[d->clot_seed[k]]++;
  n = (size_t)snprintf(line, sizeof(line),
                       "%" PetscInt_FMT ",%.8g,%" PetscInt_FMT ",%" PetscInt64_FMT, s->step, s->t,
                       d->n_clot, s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE]);
  for (PetscInt k = 0; k < d->n_seeds; k++)
    n += (size_t)snprintf(line + n, sizeof(line) - n, ",%" PetscInt_FMT, count[k]);
  snprintf(line + n, sizeof(line) - n, "\n");
  PetscCall(csv_line(d->csv, AGG_CSV, line));
  PetscFunctionReturn(0);
}

static PetscErrorCode agg_seed(sim *s, agg_data *d) {
  PetscInt n;
  PetscInt64 gids[AGGLOMERATION_MAX_SEEDS], sorted[AGGLOMERATION_MAX_SEEDS];
  PetscInt idx[AGGLOMERATION_MAX_SEEDS];
  PetscFunctionBeginUser;
  if (d->n_points)
    PetscCall(agg_seeds_from_points(s, d, &n, gids));
  else
    PetscCall(d->chooser(s, d->chooser_ctx, &n, gids));
  PetscCheck(n >= 1 && n <= AGGLOMERATION_MAX_SEEDS, s->comm, PETSC_ERR_PLIB,
             "agglomeration: %" PetscInt_FMT " seeds", n);
  for (PetscInt k = 0; k < n; k++) {
    for (PetscInt q = 0; q < k; q++)
      PetscCheck(gids[q] != gids[k], s->comm, PETSC_ERR_ARG_WRONG,
                 "-agglomeration_seeds: seeds %" PetscInt_FMT " and %" PetscInt_FMT
                 " are the same particle (gid %" PetscInt64_FMT "): give points farther apart",
                 q + 1, k + 1, gids[k]);
    d->seed_gid[k] = sorted[k] = gids[k];
    idx[k] = k;
  }
  d->n_seeds = n;
  PetscCall(agg_add_members(d, n, gids, idx));
  qsort(sorted, (size_t)n, sizeof(PetscInt64), cmp_gid);
  agg_mark_owned(s, n, sorted);
  PetscCall(
      PetscPrintf(s->comm, "agglomeration: t = %g s, %" PetscInt_FMT " seed(s), gid", s->t, n));
  for (PetscInt k = 0; k < n; k++)
    PetscCall(PetscPrintf(s->comm, " %" PetscInt64_FMT, gids[k]));
  PetscCall(PetscPrintf(s->comm, "\n"));
  PetscFunctionReturn(0);
}

/* Clot bonds of each owned clot particle in mine[] (sorted by gid): the store holds
 * every bond of an owned particle. */
static PetscErrorCode agg_count_bonds(const topology *t, agglomeration_point *mine, PetscInt n) {
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    if (t->bond_type[b] != AGGLOMERATION_BOND_TYPE)
      continue;
    for (int e = 0; e < 2; e++) {
      const agglomeration_point key = {t->bond_gid[b][e], {0, 0}, 0};
      agglomeration_point *p = bsearch(&key, mine, (size_t)n, sizeof(*mine), cmp_point);
      if (p)
        p->n_bonds++;
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode agg_grow(sim *s, agg_data *d, PetscInt64 event) {
  const particles *ps = &s->ps;
  topology *t = s->topo;
  agglomeration_point *mine, *clot, *cand;
  PetscInt n_mine = 0, n_clot, n_cand;
  PetscFunctionBeginUser;
  /* owned clot particles, with their clot bond counts */
  PetscCall(PetscMalloc1(ps->n_owned + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_CLOT) {
      mine[n_mine].gid = ps->gid[i];
      mine[n_mine].x[0] = ps->x[i][0];
      mine[n_mine].x[1] = ps->x[i][1];
      mine[n_mine++].n_bonds = 0;
    }
  qsort(mine, (size_t)n_mine, sizeof(*mine), cmp_point);
  PetscCall(agg_count_bonds(t, mine, n_mine));
  PetscCall(agg_allgather(s, mine, n_mine, &clot, &n_clot));
  PetscCheck(n_clot == d->n_clot, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "agglomeration: %" PetscInt_FMT " clot particles found, %" PetscInt_FMT " expected",
             n_clot, d->n_clot);
  /* candidates: liquid particles within R_max of a clot particle */
  n_mine = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    for (PetscInt p = 0; p < n_clot; p++) {
      double dd[2] = {ps->x[i][0] - clot[p].x[0], ps->x[i][1] - clot[p].x[1]};
      domain_min_image(&s->dom, dd);
      if (dd[0] * dd[0] + dd[1] * dd[1] < d->rmax * d->rmax) {
        mine[n_mine].gid = ps->gid[i];
        mine[n_mine].x[0] = ps->x[i][0];
        mine[n_mine].x[1] = ps->x[i][1];
        mine[n_mine++].n_bonds = 0;
        break;
      }
    }
  }
  PetscCall(agg_allgather(s, mine, n_mine, &cand, &n_cand));
  PetscCall(PetscFree(mine));

  const agglomeration_rules rules = {
      d->rmax, d->probability, d->max_bonds, (uint64_t)d->rng_seed, (uint64_t)event, &s->dom};
  const PetscInt cap = PetscMin(n_clot, n_cand) + 1;
  PetscInt n_pairs, (*pairs)[2], *seed, *types, n_given = 0;
  double *r0, *r0_given;
  PetscInt64 *joined, (*given)[2], *og;
  PetscInt *orow;
  PetscCall(PetscMalloc4(cap, &pairs, cap, &r0, cap, &joined, cap, &seed));
  PetscCall(PetscMalloc3(cap, &given, cap, &types, cap, &r0_given));
  PetscCall(agglomeration_pair(&rules, clot, n_clot, cand, n_cand, &n_pairs, pairs, r0));
  /* every rank took the same decisions: the owner of each bond's clot end gives it */
  PetscCall(topology_owned_lookup(ps, &og, &orow));
  for (PetscInt k = 0; k < n_pairs; k++) {
    const PetscInt64 gc = clot[pairs[k][0]].gid, gf = cand[pairs[k][1]].gid;
    if (topology_lookup_row(og, orow, ps->n_owned, gc) >= 0) {
      given[n_given][0] = gc;
      given[n_given][1] = gf;
      types[n_given] = AGGLOMERATION_BOND_TYPE;
      r0_given[n_given++] = r0[k];
    }
    joined[k] = gf;
    seed[k] = d->clot_seed[agg_clot_index(d, gc)];
  }
  PetscCall(
      topology_add_bonds(t, ps, s->comm, n_given, (const PetscInt64(*)[2])given, types, r0_given));
  PetscCall(PetscFree2(og, orow));
  PetscCall(PetscFree3(given, types, r0_given));
  PetscCall(agg_add_members(d, n_pairs, joined, seed));
  qsort(joined, (size_t)n_pairs, sizeof(PetscInt64), cmp_gid);
  agg_mark_owned(s, n_pairs, joined);
  PetscCall(PetscFree4(pairs, r0, joined, seed));
  PetscCall(PetscFree(clot));
  PetscCall(PetscFree(cand));
  PetscFunctionReturn(0);
}

static double agg_event_time(const agg_data *d, PetscInt64 k) {
  return d->start + (double)k * d->interval;
}

static PetscErrorCode agglomeration_post_step(module *self, sim *s) {
  agg_data *d = self->data;
  PetscFunctionBeginUser;
  if (s->t < agg_event_time(d, d->next_event) - 0.5 * s->dt)
    PetscFunctionReturn(0);
  if (d->next_event == 0)
    PetscCall(agg_seed(s, d));
  else
    PetscCall(agg_grow(s, d, d->next_event));
  d->next_event++;
  /* types changed and bonds were added: the next step migrates and rebuilds
   * ghosts, the topology's resolution and the exclusions before its forces */
  s->force_rebuild = PETSC_TRUE;
  PetscCall(agg_write_row(s, d));
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_set_from_options(module *self, sim *s) {
  agg_data *d = self->data;
  PetscInt n = 2 * AGGLOMERATION_MAX_SEEDS;
  PetscBool set_points, start_given;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL,
                    "Clot agglomeration: bonds made at run time (module agglomeration)", NULL);
  PetscCall(options_read_real("-agglomeration_interval",
                              "Physical time between agglomeration events [s]", NULL, d->interval,
                              &d->interval, NULL));
  PetscCall(options_read_real("-agglomeration_start",
                              "Time the seeds are placed [s] (default: one interval)", NULL,
                              d->start, &d->start, &start_given));
  PetscCall(options_read_real("-agglomeration_rmax", "Capture radius R_max [m]", NULL, d->rmax,
                              &d->rmax, NULL));
  PetscCall(options_read_real("-agglomeration_probability",
                              "Probability P that a chosen pair bonds [1]", NULL, d->probability,
                              &d->probability, NULL));
  PetscCall(options_read_int("-agglomeration_max_bonds", "Most clot bonds per clot particle [1]",
                             NULL, d->max_bonds, &d->max_bonds, NULL));
  PetscCall(options_read_int("-agglomeration_seed", "Seed of the counter-based random numbers [1]",
                             NULL, d->rng_seed, &d->rng_seed, NULL));
  PetscCall(options_read_real_array(
      "-agglomeration_seeds",
      "Seed points x1,y1,x2,y2,... [m]: the nearest liquid particle to each starts a clot "
      "(default: chosen by the scene)",
      NULL, d->points, &n, &set_points));
  PetscCall(options_read_real("-agglomeration_bond_k",
                              "Clot bond stiffness K [J/m^2] (default: the scene's bond K)", NULL,
                              d->bond_k, &d->bond_k, &d->k_set));
  PetscOptionsEnd();
  d->n_points = set_points ? n : 0;
  d->start_set = d->start_set || start_given ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(d->interval > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_interval must be > 0 (got %g s)", d->interval);
  if (!d->start_set)
    d->start = d->interval;
  PetscCheck(d->start >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_start must be >= 0 (got %g s)", d->start);
  PetscCheck(d->rmax > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_rmax must be > 0 (got %g m)", d->rmax);
  PetscCheck(d->probability >= 0 && d->probability <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_probability must lie in [0, 1] (got %g)", d->probability);
  PetscCheck(d->max_bonds >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_max_bonds must be >= 1 (got %" PetscInt_FMT ")", d->max_bonds);
  PetscCheck(d->rng_seed >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_seed must be >= 0 (got %" PetscInt_FMT ")", d->rng_seed);
  PetscCheck(!set_points || (n >= 2 && n % 2 == 0), s->comm, PETSC_ERR_ARG_SIZ,
             "-agglomeration_seeds takes pairs x,y (got %" PetscInt_FMT
             " values, at most %d points)",
             n, AGGLOMERATION_MAX_SEEDS);
  PetscCheck(set_points || d->chooser, s->comm, PETSC_ERR_ARG_WRONG,
             "-agglomeration_seeds x1,y1,... is needed: scene '%s' does not choose seeds",
             s->scene_name);
  PetscCheck(!d->k_set || d->bond_k > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-agglomeration_bond_k must be > 0 (got %g J/m^2)", d->bond_k);
  /* the ghost width must reach a stretched clot bond (made at most R_max long) */
  self->reach = 1.5 * d->rmax;
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_setup(module *self, sim *s) {
  agg_data *d = self->data;
  bond_style style;
  const bond_params *bp;
  PetscFunctionBeginUser;
  PetscCheck(s->topo, s->comm, PETSC_ERR_ORDER,
             "agglomeration needs the bonds of a bond module (solid_modules_enable)");
  PetscCall(bond_get_params(s, &style, &bp));
  PetscCheck(style == BOND_HARMONIC, s->comm, PETSC_ERR_ARG_INCOMP,
             "agglomeration: clots need -bond_style harmonic (the nonlinear bond module does not "
             "skip clot bonds)");
  PetscCheck(s->topo->n_bond_types <= AGGLOMERATION_BOND_TYPE, s->comm, PETSC_ERR_ARG_INCOMP,
             "agglomeration: the scene uses bond type %d, reserved for clot bonds",
             AGGLOMERATION_BOND_TYPE);
  if (!d->k_set)
    d->bond_k = bp->k[0];
  /* the clot bonds are this module's: the bond module leaves them to it */
  PetscCall(topology_claim_bond_type(s->topo, AGGLOMERATION_BOND_TYPE, self));
  double local = INFINITY;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (s->ps.type[i] == PTYPE_FLUID)
      local = PetscMin(local, s->ps.mass[i]);
  PetscCallMPI(MPI_Allreduce(&local, &d->m_min, 1, MPI_DOUBLE, MPI_MIN, s->comm));
  PetscCheck(isfinite(d->m_min), s->comm, PETSC_ERR_ARG_WRONG,
             "agglomeration: the scene has no liquid");
  PetscFunctionReturn(0);
}

/* the clot bonds: the harmonic law with each bond's own rest length */
static harmonic_bonds agglomeration_bonds(const module *self, double k[TOPOLOGY_MAX_TYPES]) {
  const agg_data *d = self->data;
  for (int t = 0; t < TOPOLOGY_MAX_TYPES; t++)
    k[t] = d->bond_k;
  return (harmonic_bonds){.owner = self, .k = k, .r0 = NULL};
}

static PetscErrorCode agglomeration_compute(module *self, sim *s) {
  double k[TOPOLOGY_MAX_TYPES];
  const harmonic_bonds set = agglomeration_bonds(self, k);
  PetscFunctionBeginUser;
  if (s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE] > 0)
    PetscCall(bond_harmonic_forces(s, &set));
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_virial(module *self, sim *s, double (*W)[3]) {
  double k[TOPOLOGY_MAX_TYPES];
  const harmonic_bonds set = agglomeration_bonds(self, k);
  PetscFunctionBeginUser;
  if (s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE] > 0)
    PetscCall(bond_harmonic_virial_add(s, &set, W));
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_energy(module *self, sim *s, double *e) {
  double k[TOPOLOGY_MAX_TYPES];
  const harmonic_bonds set = agglomeration_bonds(self, k);
  PetscFunctionBeginUser;
  PetscCall(bond_harmonic_energy_of(s, &set, e));
  PetscFunctionReturn(0);
}

/* Covers bonds not made yet (with -dt 0, dt is fixed at the start): the clot
 * bond K on the lightest liquid particle. */
static PetscErrorCode agglomeration_max_dt(module *self, sim *s, dt_limits *l) {
  const agg_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(dt_limits_add(l, "clot bonds", "0.2 sqrt(m/k), k = 2K_clot, m = min liquid mass",
                          SPRING_DT_FACTOR * sqrt(d->m_min / (2.0 * d->bond_k))));
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_view(module *self, sim *s, PetscViewer v) {
  const agg_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(
      v,
      "agglomeration: seeds at t = %g s, events every %g s; R_max = %g m, P = %g, at "
      "most %" PetscInt_FMT " bonds per clot particle, K = %g J/m^2, seed %" PetscInt_FMT "; %s\n",
      d->start, d->interval, d->rmax, d->probability, d->max_bonds, d->bond_k, d->rng_seed,
      d->n_points ? "seed points given" : "seeds chosen by the scene"));
  PetscFunctionReturn(0);
}

/* The bonds themselves are the topology's (checkpointed with it); their count is kept
 * here to check that the two agree on restart. */
static PetscErrorCode agglomeration_checkpoint_write(module *self, sim *s, checkpoint_io *io) {
  const agg_data *d = self->data;
  const PetscInt64 nb = s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE];
  PetscInt64 state[5] = {d->next_event, d->n_seeds, d->n_clot, nb, s->force_rebuild ? 1 : 0}, *sd;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_put_ints(io, "state", state, 5));
  if (d->n_seeds)
    PetscCall(checkpoint_put_ints(io, "seed_gid", d->seed_gid, d->n_seeds));
  if (d->n_clot) {
    PetscCall(PetscMalloc1(d->n_clot, &sd));
    for (PetscInt k = 0; k < d->n_clot; k++)
      sd[k] = d->clot_seed[k];
    PetscCall(checkpoint_put_ints(io, "clot_gid", d->clot_gid, d->n_clot));
    PetscCall(checkpoint_put_ints(io, "clot_seed", sd, d->n_clot));
    PetscCall(PetscFree(sd));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_checkpoint_read(module *self, sim *s, checkpoint_io *io) {
  agg_data *d = self->data;
  PetscInt64 state[5];
  PetscFunctionBeginUser;
  PetscCall(checkpoint_get_ints(io, "state", state, 5));
  PetscCheck(state[1] >= 0 && state[1] <= AGGLOMERATION_MAX_SEEDS && state[2] >= 0 && state[3] >= 0,
             PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "checkpoint: invalid agglomeration state");
  PetscCheck(d->n_clot == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "agglomeration: restart into a run that already made clots");
  /* the topology was read before the modules' state */
  PetscCheck(state[3] == s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE], PETSC_COMM_SELF,
             PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint: the agglomeration state counts %" PetscInt64_FMT
             " clot bonds, the topology holds %" PetscInt64_FMT,
             state[3], s->topo->n_bonds_of_type[AGGLOMERATION_BOND_TYPE]);
  d->next_event = state[0];
  d->restart_step = s->step;                              /* read before the modules' state */
  s->force_rebuild = state[4] ? PETSC_TRUE : PETSC_FALSE; /* written at an event's step */
  d->n_seeds = (PetscInt)state[1];
  if (d->n_seeds)
    PetscCall(checkpoint_get_ints(io, "seed_gid", d->seed_gid, d->n_seeds));
  const PetscInt nc = (PetscInt)state[2];
  if (nc) {
    PetscInt64 *cg, *cs;
    PetscInt *seed;
    PetscCall(PetscMalloc3(nc, &cg, nc, &cs, nc, &seed));
    PetscCall(checkpoint_get_ints(io, "clot_gid", cg, nc));
    PetscCall(checkpoint_get_ints(io, "clot_seed", cs, nc));
    for (PetscInt k = 0; k < nc; k++)
      seed[k] = (PetscInt)cs[k];
    PetscCall(agg_add_members(d, nc, cg, seed));
    PetscCall(PetscFree3(cg, cs, seed));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode agglomeration_destroy(module *self) {
  agg_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(csv_close(&d->csv, AGG_CSV));
  PetscCall(PetscFree2(d->clot_gid, d->clot_seed));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode agglomeration_set_defaults(module *m, double rmax, double start) {
  agg_data *d = m->data;
  PetscFunctionBeginUser;
  if (rmax > 0)
    d->rmax = rmax;
  if (start >= 0) {
    d->start = start;
    d->start_set = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode agglomeration_set_seed_chooser(module *m, agglomeration_seed_fn fn, void *ctx) {
  agg_data *d = m->data;
  PetscFunctionBeginUser;
  d->chooser = fn;
  d->chooser_ctx = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode agglomeration_module_create(module **m) {
  agg_data *d;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  PetscCall(PetscNew(&d));
  /* the thesis: an event every 0.5e6 steps of 1e-7 s, R_max = 2.5e-4 m, P = 0.5, 4 bonds */
  d->interval = 0.05;
  d->rmax = 2.5e-4;
  d->probability = 0.5;
  d->max_bonds = 4;
  d->rng_seed = 1;
  (*m)->name = "agglomeration";
  static const char *const reads[] = {"x", NULL}; /* ghost positions */
  (*m)->ghost_reads = reads;
  (*m)->set_from_options = agglomeration_set_from_options;
  (*m)->setup = agglomeration_setup;
  (*m)->compute = agglomeration_compute;
  (*m)->max_dt = agglomeration_max_dt;
  (*m)->view = agglomeration_view;
  (*m)->destroy = agglomeration_destroy;
  (*m)->energy = agglomeration_energy;
  (*m)->virial = agglomeration_virial;
  (*m)->checkpoint_write = agglomeration_checkpoint_write;
  (*m)->checkpoint_read = agglomeration_checkpoint_read;
  (*m)->post_step = agglomeration_post_step;
  (*m)->data = d;
  PetscFunctionReturn(0);
}
