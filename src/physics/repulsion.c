/* Module repulsion (doc/theory.md): for every listed pair of one fluid and one
 * solid/wall particle closer than r*,
 *   F_fluid = K [(r* / r)^p1 - (r* / r)^p2] r_vec/r^2  (r_vec from the other to the fluid one)
 * and, with -repulsion_bodies (scenes with several solid bodies, e.g. the
 * vein's two leaflets; needs the optional `body` field), the same force
 * between two non-fluid particles of different bodies (walls are body 0), so
 * that the leaflets cannot pass through each other or through the walls.
 * Options -repulsion_k [J], -repulsion_rstar [m], -repulsion_p1, -repulsion_p2
 * (4, 2 by default as in the thesis runs; 12, 6 allowed; any p1 > p2 >= 1).
 * Pair arithmetic in repulsion_iact.h; the (4, 2) and (12, 6) sweeps are
 * specialised (integer powers unrolled), others use a generic sweep.
 * Time-step limit: stiffness at r*, k = K (p1 - p2)/r*^2, on the reduced mass
 * of the lightest fluid and solid particles: 0.2 sqrt(mu/k).
 * With -repulsion_substeps (and -solid_substeps other than 1) the contact is
 * evaluated on the solid sub-steps, and the liquid particles within
 * r* + skin/4 of a solid or wall at the start of a step move on them too
 * (substep_members): its limit then bounds the sub-step, not the liquid's step.
 * The margin beyond r* is many times what a pair closes in one step, so a
 * particle that reaches r* during a step was already marked at its start. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/bond.h"
#include "dmhs/repulsion.h"
#include "dmhs/events.h"
#include "dmhs/fields.h"
#include "dmhs/checkpoint.h"
#include "repulsion_iact.h"
#include "virial_iact.h"

typedef struct {
  double K, rstar;
  PetscInt p1, p2;
  PetscBool bodies;   /* also between different solid bodies */
  PetscBool substeps; /* evaluated on the solid sub-steps (multi-rate contact) */
  double r2_min;   /* closest approach of a repelling pair at the last compute [m^2] (inf: none) */
  double m_min[2]; /* lightest liquid and solid particle [kg] (masses never change) */
  PetscBool have_masses;
  /* the pairs that can repel before the next build: indices into the pair list, in its
   * order (the same sums), filtered at each build (repulsion_filter) */
  PetscInt *sub, n_sub, n_alloc_sub;
  PetscInt64 sub_generation;
} repulsion_data;

PetscErrorCode repulsion_set_bodies(module *m, PetscBool on) {
  repulsion_data *d = m->data;
  PetscFunctionBeginUser;
  d->bodies = on;
  PetscFunctionReturn(0);
}

PetscErrorCode repulsion_set_default(module *m, double K, double rstar, PetscInt p1, PetscInt p2) {
  repulsion_data *d = m->data;
  PetscFunctionBeginUser;
  d->K = K;
  d->rstar = rstar;
  d->p1 = p1;
  d->p2 = p2;
  m->reach = rstar;
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_set_from_options(module *self, sim *s) {
  repulsion_data *d = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(
      s->comm, NULL,
      "Solid/wall-fluid repulsion f = K[(r* / r)^p1 - (r* / r)^p2] r_vec/r^2 (module repulsion)",
      NULL);
  PetscCall(options_read_real("-repulsion_k", "Repulsion strength K [J]", NULL, d->K, &d->K, NULL));
  PetscCall(options_read_real("-repulsion_rstar", "Repulsion range r* [m]", NULL, d->rstar,
                              &d->rstar, NULL));
  PetscCall(options_read_int("-repulsion_p1", "Repulsive exponent p1 [1] (4 or 12 usual)", NULL,
                             d->p1, &d->p1, NULL));
  PetscCall(options_read_int("-repulsion_p2", "Attractive exponent p2 [1] (2 or 6 usual)", NULL,
                             d->p2, &d->p2, NULL));
  PetscCall(options_read_bool(
      "-repulsion_bodies",
      "Also repel non-fluid particles of different solid bodies (scenes that number bodies)", NULL,
      d->bodies, &d->bodies, NULL));
  PetscCall(options_read_bool(
      "-repulsion_substeps",
      "With -solid_substeps other than 1: evaluate the repulsion on the solid sub-steps and move "
      "the liquid particles in contact on them (multi-rate contact: its limit bounds the "
      "sub-step, not the step)",
      NULL, d->substeps, &d->substeps, NULL));
  PetscOptionsEnd();
  self->solid_internal = d->substeps;
  PetscCheck(!d->bodies || fields_enabled("body"), s->comm, PETSC_ERR_ARG_INCOMP,
             "-repulsion_bodies: scene '%s' does not number its solid bodies", s->scene_name);
  PetscCheck(d->K >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-repulsion_k must be >= 0 (got %g J)",
             d->K);
  PetscCheck(d->rstar > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-repulsion_rstar must be > 0 (got %g m)", d->rstar);
  PetscCheck(d->p2 >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-repulsion_p2 must be >= 1 (got %" PetscInt_FMT ")", d->p2);
  PetscCheck(d->p1 > d->p2 && d->p1 <= 24, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-repulsion_p1 must lie in [%" PetscInt_FMT ", 24] (above -repulsion_p2: p1 <= p2 "
             "would attract; got %" PetscInt_FMT ")",
             d->p2 + 1, d->p1);
  self->reach = d->rstar;
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt n_pairs;             /* entries of sub */
  const PetscInt *restrict sub; /* indices into the pair list */
  const PetscInt *restrict pi, *restrict pj;
  const double (*restrict x)[2];
  const double *restrict mass;
  double (*restrict a)[2];
  double K, rstar;
} repulsion_args;

/* Liquid for the repulsion: fluid or clot (a clot particle was liquid and stays among it). */
static inline __attribute__((always_inline)) int repulsion_liquid(PetscInt type) {
  return type == PTYPE_FLUID || type == PTYPE_CLOT;
}

/* Does the pair (i, j) repel? One liquid and one solid/wall; with bodies, also two solid
 * or wall particles of different bodies. */
static inline __attribute__((always_inline)) int
repulsion_acts(int bodies, const PetscInt *type, const PetscInt *body, PetscInt i, PetscInt j) {
  const int fi = repulsion_liquid(type[i]), fj = repulsion_liquid(type[j]);
  if (fi != fj)
    return 1;
  return bodies && !fi && body[i] != body[j];
}

/* Returns the smallest r^2 of a repelling pair (the stiffness there bounds dt). */
static inline __attribute__((always_inline)) double repulsion_sweep(int p1, int p2,
                                                                    const repulsion_args *A) {
  const PetscInt *restrict pi = A->pi, *restrict pj = A->pj;
  const double(*restrict x)[2] = A->x;
  const double *restrict mass = A->mass;
  double(*restrict a)[2] = A->a;
  const double K = A->K, rstar = A->rstar, rs2 = rstar * rstar;
  double r2_min = INFINITY;
  for (PetscInt q = 0; q < A->n_pairs; q++) {
    const PetscInt k = A->sub[q], i = pi[k], j = pj[k];
    const double d[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double r2 = d[0] * d[0] + d[1] * d[1];
    if (r2 >= rs2)
      continue;
    r2_min = r2 < r2_min ? r2 : r2_min;
    const double fr = repulsion_iact(K, rstar, p1, p2, r2);
    const double fi = fr / mass[i], fj = fr / mass[j];
    a[i][0] += fi * d[0];
    a[i][1] += fi * d[1];
    a[j][0] -= fj * d[0];
    a[j][1] -= fj * d[1];
  }
  return r2_min;
}

static double sweep_4_2(const repulsion_args *A) {
  return repulsion_sweep(4, 2, A);
}
static double sweep_12_6(const repulsion_args *A) {
  return repulsion_sweep(12, 6, A);
}

/* The margin of substep_members beyond r*, as a fraction of the skin */
#define REPULSION_MEMBER_MARGIN 0.25

/* Once per build: the listed pairs that repel (types and bodies change only at a build) and
 * lay within r* + skin. Between builds every particle moves less than half the skin from
 * where the build saw it (else a rebuild), so no other pair comes within r*. With sub-steps,
 * within r* + (2 + margin) skin: the filter may run after the build (a restart's first step),
 * and every pair within r* + margin skin at any later step before the next build must be
 * in it, so that the marked rows do not depend on when it ran. */
static PetscErrorCode repulsion_filter(repulsion_data *d, sim *s) {
  const particles *ps = &s->ps;
  const double reach = d->rstar + (d->substeps ? 2.0 + REPULSION_MEMBER_MARGIN : 1.0) * s->skin,
               reach2 = reach * reach;
  PetscFunctionBeginUser;
  if (s->cel.n_pairs > d->n_alloc_sub) {
    PetscCall(PetscFree(d->sub));
    d->n_alloc_sub = s->cel.n_pairs + s->cel.n_pairs / 4;
    PetscCall(PetscMalloc1(d->n_alloc_sub, &d->sub));
  }
  d->n_sub = 0;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = s->cel.pair_i[k], j = s->cel.pair_j[k];
    if (!repulsion_acts(d->bodies, ps->type, ps->body, i, j))
      continue;
    const double dx = ps->x[i][0] - ps->x[j][0], dy = ps->x[i][1] - ps->x[j][1];
    if (dx * dx + dy * dy < reach2)
      d->sub[d->n_sub++] = k;
  }
  d->sub_generation = s->cel.generation;
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_compute(module *self, sim *s) {
  repulsion_data *d = self->data;
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.repulsion, 0, 0, 0, 0));
  if (d->sub_generation != s->cel.generation)
    PetscCall(repulsion_filter(d, s));
  const repulsion_args A = {.n_pairs = d->n_sub,
                            .sub = d->sub,
                            .pi = s->cel.pair_i,
                            .pj = s->cel.pair_j,
                            .x = (const double(*)[2])ps->x,
                            .mass = ps->mass,
                            .a = ps->a,
                            .K = d->K,
                            .rstar = d->rstar};
  if (d->p1 == 4 && d->p2 == 2)
    d->r2_min = sweep_4_2(&A);
  else if (d->p1 == 12 && d->p2 == 6)
    d->r2_min = sweep_12_6(&A);
  else
    d->r2_min = repulsion_sweep((int)d->p1, (int)d->p2, &A); /* generic: loop powers */
  PetscCall(PetscLogFlops(10.0 * (double)d->n_sub)); /* r^2 and its test; ~20 more inside r* */
  PetscCall(PetscLogEventEnd(events.repulsion, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The owned liquid rows with a repelling partner within r* + margin skin now: their motion
 * belongs to the sub-steps (the walls' and solids' partners alike; solids are marked already). */
static PetscErrorCode repulsion_substep_members(module *self, sim *s, PetscInt *mark) {
  repulsion_data *d = self->data;
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  if (d->sub_generation != s->cel.generation)
    PetscCall(repulsion_filter(d, s));
  const double r_m = d->rstar + REPULSION_MEMBER_MARGIN * s->skin, r_m2 = r_m * r_m;
  const PetscInt *pi = s->cel.pair_i, *pj = s->cel.pair_j, n_owned = ps->n_owned;
  for (PetscInt q = 0; q < d->n_sub; q++) {
    const PetscInt k = d->sub[q], i = pi[k], j = pj[k];
    const double dx = ps->x[i][0] - ps->x[j][0], dy = ps->x[i][1] - ps->x[j][1];
    if (dx * dx + dy * dy >= r_m2)
      continue;
    if (i < n_owned && repulsion_liquid(ps->type[i]))
      mark[i] = 1;
    if (j < n_owned && repulsion_liquid(ps->type[j]))
      mark[j] = 1;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_energy_sum(module *self, sim *s, double *e) {
  const repulsion_data *d = self->data;
  const particles *ps = &s->ps;
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = s->cel.pair_i[k], j = s->cel.pair_j[k];
    if (!repulsion_acts(d->bodies, ps->type, ps->body, i, j))
      continue;
    const double w = 0.5 * ((i < ps->n_owned) + (j < ps->n_owned)); /* share owned here */
    local += w * repulsion_energy(d->K, d->rstar, (int)d->p1, (int)d->p2,
                                  hypot(ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]));
  }
  PetscCallMPI(MPI_Allreduce(&local, e, 1, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

/* Pair virial: both particles get -1/2 d (x) F_i, F_i = fr d, d = x_i - x_j. */
static PetscErrorCode repulsion_virial(module *self, sim *s, double (*W)[3]) {
  const repulsion_data *d = self->data;
  const particles *ps = &s->ps;
  const double rs2 = d->rstar * d->rstar;
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = s->cel.pair_i[k], j = s->cel.pair_j[k];
    if (!repulsion_acts(d->bodies, ps->type, ps->body, i, j))
      continue;
    const double r[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double r2 = r[0] * r[0] + r[1] * r[1];
    if (r2 >= rs2)
      continue;
    const double fr = repulsion_iact(d->K, d->rstar, (int)d->p1, (int)d->p2, r2);
    virial_pair_add(W, i, j, fr, r);
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_max_dt(module *self, sim *s, dt_limits *l) {
  repulsion_data *d = self->data;
  double m[3];
  PetscFunctionBeginUser;
  /* evaluated before every step: the masses once, the closest approach each time */
  if (!d->have_masses) {
    double local[2] = {INFINITY, INFINITY};
    for (PetscInt i = 0; i < s->ps.n_owned; i++) {
      if (s->ps.type[i] == PTYPE_FLUID)
        local[0] = PetscMin(local[0], s->ps.mass[i]);
      if (s->ps.type[i] == PTYPE_SOLID)
        local[1] = PetscMin(local[1], s->ps.mass[i]);
    }
    PetscCallMPI(MPI_Allreduce(local, d->m_min, 2, MPI_DOUBLE, MPI_MIN, s->comm));
    d->have_masses = PETSC_TRUE;
  }
  PetscCallMPI(MPI_Allreduce(&d->r2_min, &m[2], 1, MPI_DOUBLE, MPI_MIN, s->comm));
  m[0] = d->m_min[0];
  m[1] = d->m_min[1];
  if (!isfinite(m[0]) || d->K <= 0)
    PetscFunctionReturn(0);
  /* against a wall the fluid particle moves alone; against a solid, both do;
   * two solids of different bodies: half the solid mass */
  double mu = isfinite(m[1]) ? m[0] * m[1] / (m[0] + m[1]) : m[0];
  if (d->bodies && isfinite(m[1]))
    mu = PetscMin(mu, 0.5 * m[1]);
  /* -dF/dr = K [(p1+1) s^p1 - (p2+1) s^p2]/r^2 with s = r* over r: K (p1-p2)/r*^2 at r*,
   * stiffer at the closest approach of the last force evaluation */
  double k = d->K * (double)(d->p1 - d->p2) / (d->rstar * d->rstar);
  if (isfinite(m[2]) && m[2] > 0) {
    const double r = sqrt(m[2]), sr = d->rstar / r;
    const double k_close = d->K *
                           ((double)(d->p1 + 1) * repulsion_ipow(sr, (int)d->p1) -
                            (double)(d->p2 + 1) * repulsion_ipow(sr, (int)d->p2)) /
                           m[2];
    k = PetscMax(k, k_close);
  }
  PetscCall(dt_limits_add(l, "repulsion",
                          "0.2 sqrt(mu/k), k = -dF/dr at the closest approach (>= r*)",
                          SPRING_DT_FACTOR * sqrt(mu / k)));
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_view(module *self, sim *s, PetscViewer v) {
  const repulsion_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(
      v,
      "repulsion: solid/wall-fluid%s, K = %g J, r* = %g m, p1 = %" PetscInt_FMT
      ", p2 = %" PetscInt_FMT "%s\n",
      d->bodies ? " and between solid bodies" : "", d->K, d->rstar, d->p1, d->p2,
      d->substeps ? "; on the solid sub-steps, with the liquid in contact (-repulsion_substeps)"
                  : ""));
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_destroy(module *self) {
  repulsion_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(d->sub));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

/* The closest approach of the last force evaluation bounds the next dt: a
 * restart (which does not evaluate forces again) needs it. Stored as the
 * global value, so any rank count reads the same. */
static PetscErrorCode repulsion_checkpoint_write(module *self, sim *s, struct checkpoint_io *io) {
  const repulsion_data *d = self->data;
  double r2_min;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&d->r2_min, &r2_min, 1, MPI_DOUBLE, MPI_MIN, s->comm));
  PetscCall(checkpoint_put_reals(io, "r2_min", &r2_min, 1));
  PetscFunctionReturn(0);
}

static PetscErrorCode repulsion_checkpoint_read(module *self, sim *s, struct checkpoint_io *io) {
  repulsion_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_get_reals(io, "r2_min", &d->r2_min, 1));
  PetscFunctionReturn(0);
}

PetscErrorCode repulsion_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "repulsion";
  static const char *const reads[] = {"x", NULL}; /* ghost positions */
  (*m)->ghost_reads = reads;
  (*m)->needs = MODULE_NEEDS_PAIRS;
  (*m)->set_from_options = repulsion_set_from_options;
  (*m)->compute = repulsion_compute;
  (*m)->max_dt = repulsion_max_dt;
  (*m)->substep_members = repulsion_substep_members;
  (*m)->view = repulsion_view;
  (*m)->destroy = repulsion_destroy;
  (*m)->energy = repulsion_energy_sum;
  (*m)->virial = repulsion_virial;
  (*m)->checkpoint_write = repulsion_checkpoint_write;
  (*m)->checkpoint_read = repulsion_checkpoint_read;
  PetscCall(PetscNew((repulsion_data **)&(*m)->data));
  ((repulsion_data *)(*m)->data)->sub_generation = -1; /* filtered at the first compute */
  /* the vein case's coupling (doc/cases.md) */
  PetscCall(repulsion_set_default(*m, 4e-4, 1e-4, 4, 2));
  PetscFunctionReturn(0);
}
