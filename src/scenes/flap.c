/* Scene flap (a coupled check): a flexible two-layer mass-spring flap
 * (solid_strip, SPH + bonds + angles) standing on the lower wall of a
 * periodic channel flow driven by a body force on the liquid. The flap's
 * lowest row is part of the wall (clamped). The liquid sees the flap through
 * the SPH sums (no-slip) and the solid/wall-fluid repulsion (no-penetration).
 *
 * Diagnostics, <output_dir>/flap.csv every output interval:
 *   t, tip_dx, tip_dy [m] (mean displacement of the top row),
 *   crossings (cumulative count of fluid particles that changed side of the
 *   flap's mid-line while beside it: must stay 0),
 *   slip (the liquid's velocity extrapolated onto the flap's faces, relative
 *   to the flap, over the largest fluid speed: see flap_slip), near (the first
 *   fluid layer's speed relative to the flap, same scale), u_max [m/s];
 * and at the end <output_dir>/flap-particles.csv (x, y, vx, vy, type, rows in
 * gid order whatever the rank count) for plots.
 * A restart continues flap.csv (csv.h); the crossing counter's state (count
 * and side of every fluid gid) travels in the checkpoint. */
#include <math.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/gather.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/body_force.h"
#include "dmhs/solid_load.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "solid_strip.h"

typedef struct {
  PetscInt nx, ny;    /* liquid lattice (before the flap is cut out) */
  PetscInt flap_x;    /* lattice column of the flap's upstream layer */
  PetscInt flap_rows; /* flap rows above the wall */
  double dx, solid_density_ratio;
  solid_strip st;
  module *body, *rep;
  PetscInt n_fluid;  /* fluid gids are 0 .. n_fluid-1 */
  signed char *side; /* per fluid gid: -1/+1 beside the flap, 0 = not beside */
  PetscInt crossings;
  /* mpi: the strip's particles (2c + l) replicated on every rank, refreshed per use */
  double (*sx)[2], (*sv)[2], (*sx0)[2];
  FILE *csv;
} flap_data;

static PetscErrorCode flap_set_from_options(scene *self, sim *s) {
  flap_data *f = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene flap (flexible flap in a periodic channel flow)", NULL);
  PetscCall(PetscOptionsInt("-flap_nx", "Liquid lattice columns (periodic length = nx dx) [1]",
                            NULL, f->nx, &f->nx, NULL));
  PetscCall(PetscOptionsInt("-flap_ny", "Liquid lattice rows (channel width = ny dx) [1]", NULL,
                            f->ny, &f->ny, NULL));
  PetscCall(PetscOptionsReal("-flap_dx",
                             "Particle spacing dx [m] (also the flap's bond rest length)", NULL,
                             f->dx, &f->dx, NULL));
  PetscCall(PetscOptionsInt("-flap_rows", "Flap height in rows above the wall [1]", NULL,
                            f->flap_rows, &f->flap_rows, NULL));
  PetscCall(PetscOptionsInt("-flap_column", "Lattice column of the flap's upstream layer [1]", NULL,
                            f->flap_x, &f->flap_x, NULL));
  PetscCall(PetscOptionsReal("-flap_density_ratio", "Flap particle mass / liquid particle mass [1]",
                             NULL, f->solid_density_ratio, &f->solid_density_ratio, NULL));
  PetscOptionsEnd();
  PetscCheck(f->nx > 4 && f->ny > 4 && f->dx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_nx, -flap_ny must be > 4 and -flap_dx > 0");
  PetscCheck(f->flap_rows >= 2 && f->flap_rows < f->ny - 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_rows must lie in [2, -flap_ny - 3] (got %" PetscInt_FMT ")", f->flap_rows);
  PetscCheck(f->flap_x >= 0 && f->flap_x + 1 < f->nx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_column must lie in [0, -flap_nx - 2]");
  PetscCheck(f->solid_density_ratio > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-flap_density_ratio must be > 0");
  s->dx = f->dx;
  /* A viscous liquid so that the flow settles in a short run (override with -sph_*).
   * c0: the flap carries most of the drive, F ~ rho g (channel area), as a
   * pressure jump dp ~ F/L of a few Pa across it; Tait liquid cannot hold a
   * tension below -B = -c0^2 rho0/7 (1.4 Pa at c0 = 0.1 m/s: a void opened
   * behind the tip and the density varied 20 %). c0 = 1 m/s gives B = 143 Pa,
   * density variations ~1 %, and costs nothing: dt is set by the bonds. */
  module *sph;
  PetscCall(fields_enable("x0")); /* the flap's particle CSV: displacements */
  PetscCall(modules_enable(s, "sph", &sph));
  PetscCall(sph_set_liquid(sph, 2.5 * f->dx, 1000.0, 1.0, 1e-4)); /* h, rho0, c0, nu */
  PetscCall(modules_enable(s, "body_force", &f->body));
  PetscCall(body_force_set_default(f->body, 0.5, 0.0));
  PetscCall(solid_modules_enable(s, BOND_HARMONIC));
  /* a soft flap: EI = K dx^3 + 2 k_a dx (doc/theory.md) */
  PetscCall(bond_set_default(s, 2e3, f->dx, 0.5 * f->dx));
  PetscCall(angle_set_default(s, 1e-5, 90.0));
  PetscCall(modules_enable(s, "repulsion", &f->rep));
  PetscCall(repulsion_set_default(f->rep, 1e-6, f->dx, 4, 2));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  flap_data *f = self->data;
  const double dx = f->dx, m = sp->rho0 * dx * dx, zero[2] = {0, 0};
  const PetscInt layers = (PetscInt)ceil(sp->h / dx - 1e-9);
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  s->dom.lo[0] = 0;
  s->dom.hi[0] = f->nx * dx;
  s->dom.periodic[0] = PETSC_TRUE;
  s->dom.lo[1] = -layers * dx;
  s->dom.hi[1] = (f->ny + layers) * dx;
  s->dom.periodic[1] = PETSC_FALSE;
  /* liquid first (gids 0 .. n_fluid-1), minus the flap's sites */
  for (PetscInt j = 0; j < f->ny; j++)
    for (PetscInt i = 0; i < f->nx; i++) {
      if ((i == f->flap_x || i == f->flap_x + 1) && j < f->flap_rows)
        continue;
      const double x[2] = {(i + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, zero, m, sp->rho0, NULL));
    }
  f->n_fluid = gid;
  /* walls; the flap's clamped row replaces the top lower-wall layer at its columns */
  for (PetscInt k = 0; k < layers; k++)
    for (PetscInt i = 0; i < f->nx; i++) {
      const double below[2] = {(i + 0.5) * dx, -(k + 0.5) * dx},
                   above[2] = {(i + 0.5) * dx, (f->ny + k + 0.5) * dx};
      if (!(k == 0 && (i == f->flap_x || i == f->flap_x + 1)))
        PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, below, zero, m, sp->rho0, NULL));
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, above, zero, m, sp->rho0, NULL));
    }
  /* the flap: columns of the strip run up the channel, layer 0 upstream */
  bond_style style;
  const bond_params *bp;
  PetscCall(bond_get_params(s, &style, &bp));
  PetscCheck(
      fabs(bp->r0[0] - dx) <= 1e-9 * dx, s->comm, PETSC_ERR_ARG_INCOMP,
      "flap: -bond_r0 (%g m) must equal -flap_dx (%g m): the flap sits on the liquid's lattice",
      bp->r0[0], dx);
  f->st.n = f->flap_rows + 1;
  f->st.n_clamp = 1;
  f->st.origin[0] = (f->flap_x + 0.5) * dx;
  f->st.origin[1] = -0.5 * dx;
  f->st.along[0] = 0;
  f->st.along[1] = 1;
  f->st.across[0] = 1;
  f->st.across[1] = 0;
  f->st.spacing = dx;
  f->st.mass = f->solid_density_ratio * m;
  f->st.rho = sp->rho0;
  PetscCall(solid_strip_build(s, &f->st, &gid));
  PetscCall(PetscCalloc1(f->n_fluid, &f->side));
  PetscCall(PetscMalloc3(2 * f->st.n, &f->sx, 2 * f->st.n, &f->sv, 2 * f->st.n, &f->sx0));
  PetscFunctionReturn(0);
}

/* mpi: x, v, x0 of every strip particle on every rank: each owner fills its
 * rows, the others add zeros (exact), one Allreduce. Collective. */
static PetscErrorCode flap_gather_strip(flap_data *f, sim *s) {
  const particles *ps = &s->ps;
  const PetscInt n = 2 * f->st.n;
  double *buf;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(6 * n, &buf));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const PetscInt64 k = ps->gid[i] - f->st.first_gid;
    if (k < 0 || k >= n)
      continue;
    for (int d = 0; d < 2; d++) {
      buf[6 * k + d] = ps->x[i][d];
      buf[6 * k + 2 + d] = ps->v[i][d];
      buf[6 * k + 4 + d] = ps->x0[i][d];
    }
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, buf, (PetscMPIInt)(6 * n), MPI_DOUBLE, MPI_SUM, s->comm));
  for (PetscInt k = 0; k < n; k++)
    for (int d = 0; d < 2; d++) {
      f->sx[k][d] = buf[6 * k + d];
      f->sv[k][d] = buf[6 * k + 2 + d];
      f->sx0[k][d] = buf[6 * k + 4 + d];
    }
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

/* x of the flap's mid-line at height y (linear between rows), or NAN outside it */
static double flap_midline_x(const flap_data *f, double y) {
  const double(*x)[2] = (const double(*)[2])f->sx;
  for (PetscInt c = 0; c + 1 < f->st.n; c++) {
    const PetscInt a0 = 2 * c, a1 = 2 * c + 1, b0 = 2 * c + 2, b1 = 2 * c + 3;
    const double ya = 0.5 * (x[a0][1] + x[a1][1]), yb = 0.5 * (x[b0][1] + x[b1][1]);
    if (y < ya || y >= yb)
      continue;
    const double xa = 0.5 * (x[a0][0] + x[a1][0]), xb = 0.5 * (x[b0][0] + x[b1][0]);
    return xa + (xb - xa) * (y - ya) / (yb - ya);
  }
  return NAN;
}

static PetscErrorCode flap_count_crossings(flap_data *f, sim *s) {
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  signed char *now_all;
  /* mpi: each owner sets its particles' side, one Allreduce makes the whole
   * list; every rank then counts the same crossings */
  PetscCall(PetscCalloc1(f->n_fluid, &now_all));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->gid[i] >= f->n_fluid)
      continue;
    const double xm = flap_midline_x(f, ps->x[i][1]);
    signed char now = 0;
    if (!isnan(xm)) {
      double d[2] = {ps->x[i][0] - xm, 0};
      domain_min_image(&s->dom, d);
      if (fabs(d[0]) < 3 * f->dx)
        now = d[0] < 0 ? -1 : 1;
    }
    now_all[ps->gid[i]] = now;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, now_all, (PetscMPIInt)f->n_fluid, MPI_SIGNED_CHAR,
                             MPI_SUM, s->comm));
  for (PetscInt g = 0; g < f->n_fluid; g++) {
    if (f->side[g] && now_all[g] && f->side[g] != now_all[g])
      f->crossings++;
    f->side[g] = now_all[g];
  }
  PetscCall(PetscFree(now_all));
  PetscFunctionReturn(0);
}

/* No-slip at the flap's faces. For every free row c below the tip and each
 * face (layer l = 0 upstream, 1 downstream), with the flap's local tangent t
 * (mid-line from row c-1 to c+1) and normal n (layer 0 -> layer 1), take the
 * fluid particles in the strip |(x_i - x_P).t| < dx beside the face particle
 * P, at distance d = sigma (x_i - x_P).n - dx/2 from the face surface
 * (sigma = -1, +1 for l = 0, 1; the surface lies half a spacing outside the
 * particle centres) with -dx/2 < d <= 2.5 dx, and fit the relative velocity
 * v_i - v_P linearly in d (least squares, both components). The fit's value
 * at d = 0 is the liquid's velocity on the face relative to the flap: no-slip
 * makes it vanish, to within the discretisation. Returned, normalised by the
 * largest fluid speed u_max:
 *   slip = mean over faces and rows of |u(d = 0)|,
 *   near = mean |v_i - v_P| of the first fluid layer (d <= dx), for scale:
 *          what a slipping flap would show. */
static PetscErrorCode flap_slip(flap_data *f, sim *s, double *slip, double *near, double *umax) {
  const particles *ps = &s->ps;
  const double dx = f->dx;
  const PetscInt c0 = f->st.n_clamp, n_rows = f->st.n - 1 - c0, n_faces = 2 * PetscMax(n_rows, 0);
  double u2 = 0, sum_slip = 0, n_slip = 0, *acc;
  enum { S, SD, SDD, SU0, SU1, SUD0, SUD1, NEAR, NNEAR, N_ACC };
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(N_ACC * n_faces + 1, &acc));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID)
      u2 = PetscMax(u2, ps->v[i][0] * ps->v[i][0] + ps->v[i][1] * ps->v[i][1]);
  /* the flap's particles come from the replicated strip (sx, sv: flap_gather_strip), the
   * liquid from each rank's owned particles; the sums of every face are reduced over ranks */
  for (PetscInt c = c0; c + 1 < f->st.n; c++) {
    double t[2] = {0, 0};
    for (int l = 0; l < 2; l++) {
      t[0] += 0.5 * (f->sx[2 * (c + 1) + l][0] - f->sx[2 * (c - 1) + l][0]);
      t[1] += 0.5 * (f->sx[2 * (c + 1) + l][1] - f->sx[2 * (c - 1) + l][1]);
    }
    const double tl = hypot(t[0], t[1]);
    t[0] /= tl;
    t[1] /= tl;
    const double n[2] = {t[1], -t[0]};
    for (int l = 0; l < 2; l++) {
      const PetscInt P = 2 * c + l;
      const double sigma = l == 0 ? -1.0 : 1.0;
      double *A = acc + N_ACC * (2 * (c - c0) + l);
      for (PetscInt i = 0; i < ps->n_owned; i++) {
        if (ps->type[i] != PTYPE_FLUID)
          continue;
        double r[2] = {ps->x[i][0] - f->sx[P][0], ps->x[i][1] - f->sx[P][1]};
        domain_min_image(&s->dom, r);
        const double d = sigma * (r[0] * n[0] + r[1] * n[1]) - 0.5 * dx,
                     along = r[0] * t[0] + r[1] * t[1];
        if (fabs(along) >= dx || d <= -0.5 * dx || d > 2.5 * dx)
          continue;
        const double u[2] = {ps->v[i][0] - f->sv[P][0], ps->v[i][1] - f->sv[P][1]};
        A[S] += 1;
        A[SD] += d;
        A[SDD] += d * d;
        A[SU0] += u[0];
        A[SU1] += u[1];
        A[SUD0] += u[0] * d;
        A[SUD1] += u[1] * d;
        if (d <= dx) {
          A[NEAR] += hypot(u[0], u[1]);
          A[NNEAR] += 1;
        }
      }
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, acc, (PetscMPIInt)(N_ACC * n_faces), MPI_DOUBLE, MPI_SUM,
                             s->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &u2, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *umax = sqrt(u2);
  double sum_near = 0, n_near = 0;
  for (PetscInt k = 0; k < n_faces; k++) {
    const double *A = acc + N_ACC * k;
    sum_near += A[NEAR];
    n_near += A[NNEAR];
    const double det =
        A[S] * A[SDD] - A[SD] * A[SD]; /* S^2 var(d): needs points spread across the layers */
    if (A[S] < 3 || det < A[S] * A[S] * 0.09 * dx * dx)
      continue;
    const double u0[2] = {(A[SDD] * A[SU0] - A[SD] * A[SUD0]) / det,
                          (A[SDD] * A[SU1] - A[SD] * A[SUD1]) / det};
    sum_slip += hypot(u0[0], u0[1]);
    n_slip += 1;
  }
  PetscCall(PetscFree(acc));
  *slip = n_slip > 0 && *umax > 0 ? sum_slip / n_slip / *umax : NAN;
  *near = n_near > 0 && *umax > 0 ? sum_near / n_near / *umax : NAN;
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_tip(flap_data *f, double d[2]) {
  PetscFunctionBeginUser;
  d[0] = d[1] = 0;
  for (int l = 0; l < 2; l++) {
    const PetscInt r = 2 * (f->st.n - 1) + l;
    d[0] += 0.5 * (f->sx[r][0] - f->sx0[r][0]);
    d[1] += 0.5 * (f->sx[r][1] - f->sx0[r][1]);
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_diagnose(scene *self, sim *s) {
  flap_data *f = self->data;
  double tip[2], slip, near, umax;
  PetscFunctionBeginUser;
  PetscCall(flap_gather_strip(f, s));
  PetscCall(flap_count_crossings(f, s));
  /* rows at step 0 and at output times; a restarted run continues the file */
  if (s->step > 0 && s->t < s->next_output_t - 0.5 * s->dt)
    PetscFunctionReturn(0);
  if (s->rank == 0 && !f->csv) { /* mpi: rank 0 writes */
    char header[160];
    snprintf(header, sizeof(header),
             "# flap: height %g m, dx %g m\nt,tip_dx,tip_dy,crossings,slip,near,u_max\n",
             f->flap_rows * f->dx, f->dx);
    PetscCall(csv_open(s, "flap.csv", header, &f->csv));
  }
  PetscCall(flap_tip(f, tip));
  PetscCall(flap_slip(f, s, &slip, &near, &umax));
  if (s->rank == 0) { /* mpi: rank 0 writes */
    /* slip is undefined while the liquid is at rest (u_max = 0): an empty cell, never NaN */
    char slip_s[32] = "", near_s[32] = "";
    if (isfinite(slip))
      snprintf(slip_s, sizeof(slip_s), "%.6g", slip);
    if (isfinite(near))
      snprintf(near_s, sizeof(near_s), "%.6g", near);
    PetscCall(csv_row(f->csv, "flap.csv", "%.8g,%.8g,%.8g,%" PetscInt_FMT ",%s,%s,%.6g\n", s->t,
                      tip[0], tip[1], f->crossings, slip_s, near_s, umax));
  }
  PetscFunctionReturn(0);
}

/* The crossing counter's state: the count and the side of every fluid gid
 * (a particle that changes side between the checkpoint and the next step
 * must count as it would have without the restart). Replicated on every rank. */
static PetscErrorCode flap_checkpoint_write(scene *self, sim *s, struct checkpoint_io *io) {
  flap_data *f = self->data;
  const PetscInt64 crossings = f->crossings;
  PetscInt64 *side;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscMalloc1(f->n_fluid + 1, &side));
  for (PetscInt g = 0; g < f->n_fluid; g++)
    side[g] = f->side[g];
  PetscCall(checkpoint_put_ints(io, "flap_crossings", &crossings, 1));
  PetscCall(checkpoint_put_ints(io, "flap_side", side, f->n_fluid));
  PetscCall(PetscFree(side));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_checkpoint_read(scene *self, sim *s, struct checkpoint_io *io) {
  flap_data *f = self->data;
  PetscInt64 crossings, *side;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscMalloc1(f->n_fluid + 1, &side));
  PetscCall(checkpoint_get_ints(io, "flap_crossings", &crossings, 1));
  PetscCall(checkpoint_get_ints(io, "flap_side", side, f->n_fluid));
  f->crossings = (PetscInt)crossings;
  for (PetscInt g = 0; g < f->n_fluid; g++)
    f->side[g] = (signed char)side[g];
  PetscCall(PetscFree(side));
  PetscFunctionReturn(0);
}

#define FLAP_ROW 6 /* gid, x, y, vx, vy, type */

static int flap_compare_gid(const void *a, const void *b) {
  const double ga = ((const double *)a)[0], gb = ((const double *)b)[0];
  return (ga > gb) - (ga < gb);
}

static PetscErrorCode flap_finish(scene *self, sim *s) {
  flap_data *f = self->data;
  const particles *ps = &s->ps;
  char path[PETSC_MAX_PATH_LEN];
  double tip[2], slip, near, umax;
  PetscFunctionBeginUser;
  PetscCall(flap_gather_strip(f, s));
  PetscCall(flap_tip(f, tip));
  PetscCall(flap_slip(f, s, &slip, &near, &umax));
  PetscCall(PetscPrintf(
      s->comm,
      "flap: tip displacement (%g, %g) m (%.3g of the height), fluid crossings %" PetscInt_FMT
      ", slip on the faces |u(d=0) - v_flap|/u_max = %.3g (first fluid layer %.3g), u_max = %g "
      "m/s\n",
      tip[0], tip[1], tip[0] / (f->flap_rows * f->dx), f->crossings, slip, near, umax));
  PetscCall(csv_close(&f->csv, "flap.csv"));
  /* mpi: rows of every rank gathered to rank 0 and sorted by gid (independent of the rank count) */
  const size_t n_mine = FLAP_ROW * (size_t)ps->n_owned;
  size_t n_all;
  double *mine, *all = NULL;
  PetscCall(PetscMalloc1(n_mine + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    double *r = mine + FLAP_ROW * i;
    r[0] = (double)ps->gid[i]; /* exact below 2^53 */
    r[1] = ps->x[i][0];
    r[2] = ps->x[i][1];
    r[3] = ps->v[i][0];
    r[4] = ps->v[i][1];
    r[5] = (double)ps->type[i];
  }
  PetscCall(gather_to_root(s->comm, mine, n_mine, &all, &n_all));
  PetscCall(PetscFree(mine));
  if (s->rank == 0) {
    qsort(all, n_all / FLAP_ROW, FLAP_ROW * sizeof(double), flap_compare_gid);
    PetscCall(io_output_path(s, "flap-particles.csv", path, sizeof(path)));
    FILE *out = fopen(path, "w");
    PetscCheck(out, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path,
               strerror(errno));
    int ok = fprintf(out, "x,y,vx,vy,type\n") > 0;
    for (size_t k = 0; k < n_all && ok; k += FLAP_ROW)
      ok = fprintf(out, "%.6g,%.6g,%.6g,%.6g,%d\n", all[k + 1], all[k + 2], all[k + 3], all[k + 4],
                   (int)all[k + 5]) > 0;
    ok = fclose(out) == 0 && ok;
    PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s (disk full?)", path);
    PetscCall(PetscFree(all));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_destroy(scene *self) {
  flap_data *f = self->data;
  PetscFunctionBeginUser;
  if (f->csv)
    fclose(f->csv);
  PetscCall(PetscFree(f->side));
  PetscCall(PetscFree3(f->sx, f->sv, f->sx0));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode flap_scene_create(scene **out) {
  flap_data *f;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&f));
  f->nx = 40;
  f->ny = 24;
  f->dx = 1e-4;
  f->flap_rows = 10;
  f->flap_x = 12;
  f->solid_density_ratio = 1.0;
  (*out)->name = "flap";
  (*out)->set_from_options = flap_set_from_options;
  (*out)->build = flap_build;
  (*out)->diagnose = flap_diagnose;
  (*out)->finish = flap_finish;
  (*out)->destroy = flap_destroy;
  (*out)->checkpoint_write = flap_checkpoint_write;
  (*out)->checkpoint_read = flap_checkpoint_read;
  (*out)->data = f;
  PetscFunctionReturn(0);
}
