/* The diagnostic "intestine": counts per pocket, the front, the liquid's
 * bounds and the membrane's tightness (intestine_tracking.h). */
#include <math.h>
#include <errno.h>
#include <string.h>
#include "dmhs/intestine_tracking.h"
#include "dmhs/body_force.h"
#include "dmhs/peristalsis.h"
#include "dmhs/tracking.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "dmhs/liquid_state.h"

typedef struct {
  intestine_layout lay;
  PetscInt64 n_white0, n_red0;
  /* history of x_F for the slope (replicated) */
  double *hist_t, *hist_x;
  PetscInt n_hist, cap_hist;
  double alpha_T;                     /* alpha after one period (NAN until reached) */
  double lift_max;                    /* largest segment lift seen [m] */
  double rho_dev_max, mach_max;       /* over the output rows so far */
  PetscInt64 inside_max, through_max; /* most liquid particles in / through the membrane in a row */
  FILE *csv;
} intestine_tracking;

typedef struct {
  const intestine_tracking *c;
  PetscInt k;
} seg_sel;

static PetscBool intestine_segment_centre(const sim *s, PetscInt i, void *ctx) {
  const seg_sel *q = ctx;
  if (s->ps.type[i] != PTYPE_SOLID || s->ps.segment[i] != PERISTALSIS_SEGMENT0 + q->k)
    return PETSC_FALSE;
  return fabs(s->ps.x0[i][0] - (q->k + 0.5) * q->c->lay.b) < q->c->lay.b / 6 ? PETSC_TRUE
                                                                             : PETSC_FALSE;
}

static PetscErrorCode intestine_fluid_counts(intestine_tracking *c, sim *s, PetscInt64 *fluid,
                                             PetscInt64 *parked) {
  PetscInt64 buf[2] = {0, 0};
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    if (s->ps.type[i] == PTYPE_FLUID)
      buf[0]++;
    else if (s->ps.gid[i] < c->lay.n_fluid)
      buf[1]++;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, buf, 2, MPIU_INT64, MPI_SUM, s->comm));
  *fluid = buf[0];
  *parked = buf[1];
  PetscFunctionReturn(0);
}

/* intestine.csv and its header (csv.h: a restart keeps the rows up to the checkpoint) */
static PetscErrorCode intestine_open_csv(intestine_tracking *c, sim *s, double tw, double Tw) {
  const PetscInt np = c->lay.n_pockets;
  const size_t len = 512 + 32 * (size_t)(4 * np + 8);
  size_t at = 0;
  char *h;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(len, &h));
#define INTESTINE_HEADER(...) at += (size_t)snprintf(h + at, at < len ? len - at : 0, __VA_ARGS__)
  INTESTINE_HEADER("# intestine: %" PetscInt_FMT
                   " pockets, b %g m, dx %g m, level %g m, amplitude %g m, "
                   "t_w %g s, T_w %g s, fluid %" PetscInt64_FMT "\n",
                   np, c->lay.b, c->lay.dx, c->lay.level, c->lay.amplitude, tw, Tw, c->lay.n_fluid);
  INTESTINE_HEADER("t,sub,x_F");
  for (PetscInt k = 0; k <= np; k++)
    INTESTINE_HEADER(",white_%" PetscInt_FMT, k);
  INTESTINE_HEADER(",alpha");
  if (c->lay.red)
    for (PetscInt k = 0; k <= np; k++)
      INTESTINE_HEADER(",red_%" PetscInt_FMT, k);
  INTESTINE_HEADER(",overflow,fluid,rho_dev,mach,in_membrane,through");
  for (PetscInt k = 0; k < np; k++)
    INTESTINE_HEADER(",lift_%" PetscInt_FMT, k);
  for (PetscInt k = 0; k < np; k++)
    INTESTINE_HEADER(",s_%" PetscInt_FMT, k);
  /* where the density bound breaks: the liquid beyond 3 %, the worst particle's place */
  INTESTINE_HEADER(",rho_over_3pct,rho_worst_x,rho_worst_y");
  INTESTINE_HEADER("\n");
#undef INTESTINE_HEADER
  PetscCheck(at < len, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "intestine.csv header longer than %zu bytes", len);
  PetscCall(csv_open(s, "intestine.csv", h, &c->csv));
  PetscCall(PetscFree(h));
  PetscFunctionReturn(0);
}

/* rows at step 0 and at output times; a restarted run continues the CSV (csv.h) */
static PetscErrorCode intestine_tracking_sample(diagnostic *self, sim *s) {
  intestine_tracking *c = self->data;
  const PetscInt np = c->lay.n_pockets;
  PetscInt64 *cw, *cr, nw, nr, fluid, parked;
  double xw, xr, tw, Tw, delay;
  PetscFunctionBeginUser;
  PetscCall(peristalsis_get(c->lay.peri, &tw, &Tw, NULL, NULL, &delay));
  PetscCall(PetscCalloc2(np + 1, &cw, np + 1, &cr));
  PetscCall(tracking_count(s, INTESTINE_TRACER_WHITE, np, c->lay.b, 0.0, cw, &nw, &xw));
  if (c->lay.red)
    PetscCall(tracking_count(s, INTESTINE_TRACER_RED, np, c->lay.b, 0.0, cr, &nr, &xr));
  PetscCall(intestine_fluid_counts(c, s, &fluid, &parked));
  double rho_dev, mach;
  PetscInt64 inside, through;
  PetscCall(liquid_state_bounds(s, &rho_dev, &mach));
  PetscInt64 n_over;
  double worst[2];
  PetscCall(liquid_state_worst(s, 0.03, &n_over, worst));
  PetscCall(membrane_leak_count(s, &c->lay.mem, &inside, &through));
  c->rho_dev_max = PetscMax(c->rho_dev_max, rho_dev);
  c->mach_max = PetscMax(c->mach_max, mach);
  c->inside_max = PetscMax(c->inside_max, inside);
  c->through_max = PetscMax(c->through_max, through);
  PetscCheck(fluid + parked == c->lay.n_fluid, s->comm, PETSC_ERR_PLIB,
             "intestine: %" PetscInt64_FMT " fluid + %" PetscInt64_FMT " parked != %" PetscInt64_FMT
             " initial at t = %g s",
             fluid, parked, c->lay.n_fluid, s->t);
  if (s->step == 0) {
    c->n_white0 = nw;
    c->n_red0 = c->lay.red ? nr : 0;
  }
  const double alpha = c->n_white0 > 0 ? 1.0 - (double)cw[0] / (double)c->n_white0 : 0.0;
  double *lift;
  PetscCall(PetscMalloc1(np, &lift));
  for (PetscInt k = 0; k < np; k++) {
    seg_sel q = {c, k};
    PetscInt64 n;
    PetscCall(tracking_mean_displacement(s, intestine_segment_centre, &q, 1, &lift[k], &n));
    c->lift_max = PetscMax(c->lift_max, lift[k]);
  }
  const PetscInt sub = peristalsis_subperiod(c->lay.peri, s->t);
  /* x_F history of the squeezing phase for u_F: the first wave */
  if (s->t >= delay - 0.5 * s->dt && s->t <= delay + Tw + 0.5 * s->dt) {
    if (c->n_hist == c->cap_hist) {
      c->cap_hist = 2 * c->cap_hist + 64;
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_t));
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_x));
    }
    c->hist_t[c->n_hist] = s->t;
    c->hist_x[c->n_hist++] = xw;
  }
  if (isnan(c->alpha_T) && s->t >= delay + Tw - 0.5 * s->dt)
    c->alpha_T = alpha;
  if (s->rank == 0) { /* mpi: rank 0 writes */
    if (!c->csv)
      PetscCall(intestine_open_csv(c, s, tw, Tw));
    const size_t len = 128 + 32 * (size_t)(4 * np + 8);
    size_t at = 0;
    char *row;
    PetscCall(PetscMalloc1(len, &row));
#define INTESTINE_ROW(...) at += (size_t)snprintf(row + at, at < len ? len - at : 0, __VA_ARGS__)
    INTESTINE_ROW("%.8g,%" PetscInt_FMT ",%.10g", s->t, sub, xw);
    for (PetscInt k = 0; k <= np; k++)
      INTESTINE_ROW(",%" PetscInt64_FMT, cw[k]);
    INTESTINE_ROW(",%.8g", alpha);
    if (c->lay.red)
      for (PetscInt k = 0; k <= np; k++)
        INTESTINE_ROW(",%" PetscInt64_FMT, cr[k]);
    INTESTINE_ROW(",%" PetscInt64_FMT ",%" PetscInt64_FMT ",%.6g,%.6g,%" PetscInt64_FMT
                  ",%" PetscInt64_FMT,
                  parked, fluid, rho_dev, mach, inside, through);
    for (PetscInt k = 0; k < np; k++)
      INTESTINE_ROW(",%.8g", lift[k]);
    for (PetscInt k = 0; k < np; k++)
      INTESTINE_ROW(",%d", peristalsis_value(c->lay.peri, s->t, k));
    INTESTINE_ROW(",%" PetscInt64_FMT ",%.6g,%.6g\n", n_over, worst[0], worst[1]);
#undef INTESTINE_ROW
    PetscCheck(at < len, PETSC_COMM_SELF, PETSC_ERR_PLIB, "intestine.csv row longer than %zu bytes",
               len);
    PetscCall(csv_line(c->csv, "intestine.csv", row));
    PetscCall(PetscFree(row));
  }
  PetscCall(PetscFree(lift));
  PetscCall(PetscFree2(cw, cr));
  PetscFunctionReturn(0);
}

/* <output_dir>/intestine-summary.csv (key,value; "n/a" for an undefined
 * value, e.g. alpha when the run ends before one period), written to a
 * temporary name and renamed. */
static PetscErrorCode intestine_write_summary(sim *s, const char **keys, const double *values,
                                              PetscInt n) {
  char path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN + 8];
  PetscFunctionBeginUser;
  PetscCall(io_output_path(s, "intestine-summary.csv", path, sizeof(path)));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  FILE *f = fopen(tmp, "w");
  PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", tmp, strerror(errno));
  int ok = fprintf(f, "key,value\n") > 0;
  for (PetscInt i = 0; i < n; i++)
    ok = (isfinite(values[i]) ? fprintf(f, "%s,%.8g\n", keys[i], values[i])
                              : fprintf(f, "%s,n/a\n", keys[i])) > 0 &&
         ok;
  ok = (fclose(f) == 0) && ok;
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s", tmp);
  PetscCheck(rename(tmp, path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "cannot rename %s to %s: %s", tmp, path, strerror(errno));
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_finish(diagnostic *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  intestine_tracking *c = self->data;
  double tw, Tw, delay, uF;
  PetscInt64 fluid, parked;
  PetscFunctionBeginUser;
  PetscCall(peristalsis_get(c->lay.peri, &tw, &Tw, NULL, NULL, &delay));
  PetscCall(tracking_slope(c->hist_t, c->hist_x, c->n_hist, &uF));
  /* the initial-slope rule (when the level drops, x_F bends over): the slope
   * while pocket 0 squeezes in the first wave, the front's first advance */
  double uF0 = NAN;
  {
    PetscInt i0 = -1, n0 = 0;
    for (PetscInt i = 0; i < c->n_hist; i++)
      if (peristalsis_value(c->lay.peri, c->hist_t[i], 0) > 0) {
        if (i0 < 0)
          i0 = i;
        if (i == i0 + n0)
          n0++; /* the first contiguous squeeze only */
      }
    if (i0 >= 0)
      PetscCall(tracking_slope(c->hist_t + i0, c->hist_x + i0, n0, &uF0));
  }
  PetscCall(intestine_fluid_counts(c, s, &fluid, &parked));
  double a_body[DMHS_DIM];
  body_force_at(c->lay.body, s->t, a_body);
  const double nu = sp->nu, g = fabs(a_body[1]);
  const double Vw = c->lay.n_pockets * c->lay.b / Tw;
  const PetscBool reached = isnan(c->alpha_T) ? PETSC_FALSE : PETSC_TRUE;
  const double a = c->alpha_T;
  const double uP = a / (1 - a) * Vw / c->lay.n_pockets, uS = a * Vw;
  const PetscBool measured = c->lift_max > c->lay.dx ? PETSC_TRUE : PETSC_FALSE;
  const double h = measured ? c->lift_max : c->lay.amplitude;
  PetscCall(PetscPrintf(s->comm,
                        "intestine: fluid %" PetscInt64_FMT " in the computation + %" PetscInt64_FMT
                        " overflowed (pocket N+1, parked) = %" PetscInt64_FMT " of %" PetscInt64_FMT
                        " initial\n",
                        fluid, parked, fluid + parked, c->lay.n_fluid));
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: liquid bounds over the output rows: max |rho/rho0 - 1| %.3g, max Mach %.3g; "
      "liquid in the membrane (between its top and bottom layers) at most %" PetscInt64_FMT
      ", through it %" PetscInt64_FMT " particles\n",
      c->rho_dev_max, c->mach_max, c->inside_max, c->through_max));
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: front velocity u_F = %g m/s (least squares of x_F over %" PetscInt_FMT
      " rows, t in [%g, %g] s)\n",
      uF, c->n_hist, c->n_hist ? c->hist_t[0] : NAN, c->n_hist ? c->hist_t[c->n_hist - 1] : NAN));
  PetscCall(PetscPrintf(
      s->comm, "intestine: initial front velocity (while pocket 0 squeezes) u_F0 = %g m/s\n", uF0));
  PetscCall(PetscPrintf(s->comm, "intestine: V_w = (N+1) b / T_w = %g m/s (T_w = %g s)\n", Vw, Tw));
  if (reached)
    PetscCall(PetscPrintf(s->comm,
                          "intestine: alpha after one period = %g, u_P = alpha/(1-alpha) V_w/(N+1) "
                          "= %g m/s, u_S = alpha V_w = %g m/s\n",
                          a, uP, uS));
  else
    PetscCall(PetscPrintf(s->comm,
                          "intestine: alpha after one period: not reached (t_end < delay + T_w = "
                          "%g s); u_P, u_S undefined\n",
                          delay + Tw));
  PetscCall(PetscPrintf(s->comm,
                        "intestine: h = %g m (%s), Re = b u_F/nu = %g, Ga = h^3 g/nu^2 = %g, Fr = "
                        "V_w/sqrt(g h) = %g, Lambda = h/L = %g\n",
                        h,
                        measured ? "largest measured segment lift"
                                 : "configured amplitude A: no lift above dx measured",
                        c->lay.b * uF / nu, h * h * h * g / (nu * nu), Vw / sqrt(g * h),
                        h / c->lay.level));
  PetscCall(csv_close(&c->csv, "intestine.csv"));
  if (s->rank == 0) {
    const double Re = c->lay.b * uF / nu, Ga = h * h * h * g / (nu * nu), Fr = Vw / sqrt(g * h),
                 Lambda = h / c->lay.level;
    const double values[] = {c->lay.b,
                             c->lay.level,
                             nu,
                             Tw,
                             Vw,
                             uF,
                             uF0,
                             a,
                             uP,
                             uS,
                             h,
                             Re,
                             Ga,
                             Fr,
                             Lambda,
                             c->rho_dev_max,
                             c->mach_max,
                             (double)c->inside_max,
                             (double)c->through_max,
                             (double)fluid,
                             (double)parked,
                             s->t};
    static const char *keys[] = {
        "b",           "level",   "nu",       "T_w",         "V_w",      "u_F",
        "u_F_initial", "alpha_T", "u_P",      "u_S",         "h",        "Re",
        "Ga",          "Fr",      "Lambda",   "rho_dev_max", "mach_max", "in_membrane_max",
        "through_max", "fluid",   "overflow", "t_end"};
    PetscCall(intestine_write_summary(s, keys, values, (PetscInt)(sizeof(keys) / sizeof(keys[0]))));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_checkpoint_write(diagnostic *self, sim *s,
                                                          checkpoint_io *io) {
  intestine_tracking *c = self->data;
  const PetscInt64 ints[5] = {c->n_white0, c->n_red0, c->n_hist, c->inside_max, c->through_max};
  const double reals[4] = {c->alpha_T, c->lift_max, c->rho_dev_max, c->mach_max};
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "intestine_ints", ints, 5));
  PetscCall(checkpoint_put_reals(io, "intestine_reals", reals, 4));
  if (c->n_hist) {
    PetscCall(checkpoint_put_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_put_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_checkpoint_read(diagnostic *self, sim *s,
                                                         checkpoint_io *io) {
  intestine_tracking *c = self->data;
  PetscInt64 ints[5];
  double reals[4];
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_get_ints(io, "intestine_ints", ints, 5));
  PetscCall(checkpoint_get_reals(io, "intestine_reals", reals, 4));
  c->n_white0 = ints[0];
  c->n_red0 = ints[1];
  c->n_hist = c->cap_hist = (PetscInt)ints[2];
  c->alpha_T = reals[0];
  c->lift_max = reals[1];
  c->rho_dev_max = reals[2];
  c->mach_max = reals[3];
  c->inside_max = ints[3];
  c->through_max = ints[4];
  PetscCall(PetscFree(c->hist_t));
  PetscCall(PetscFree(c->hist_x));
  if (c->n_hist) {
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_t));
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_x));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_destroy(diagnostic *self) {
  intestine_tracking *c = self->data;
  PetscFunctionBeginUser;
  if (c->csv)
    fclose(c->csv);
  PetscCall(PetscFree(c->hist_t));
  PetscCall(PetscFree(c->hist_x));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode intestine_tracking_register(sim *s, const intestine_layout *lay) {
  diagnostic *d;
  intestine_tracking *c;
  PetscFunctionBeginUser;
  PetscCall(diagnostic_create("intestine", &d));
  PetscCall(PetscNew(&c));
  c->lay = *lay;
  c->alpha_T = NAN;
  d->data = c;
  d->output = "intestine.csv";
  d->when.at_outputs = PETSC_TRUE;
  d->sample = intestine_tracking_sample;
  d->finish = intestine_tracking_finish;
  d->destroy = intestine_tracking_destroy;
  d->checkpoint_write = intestine_tracking_checkpoint_write;
  d->checkpoint_read = intestine_tracking_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  PetscFunctionReturn(0);
}
