/* The diagnostic "intestine": counts per pocket, the front, the liquid's
 * bounds and the membrane's tightness (intestine_tracking.h); at the end the
 * measures of intestine_measures.h from the rows it kept (t, x_F, alpha). */
#include <math.h>
#include <errno.h>
#include <string.h>
#include "intestine_tracking.h"
#include "dmhs/diagnostics.h"
#include "dmhs/io.h"
#include "dmhs/sph.h"
#include "dmhs/body_force.h"
#include "dmhs/peristalsis.h"
#include "dmhs/tracking.h"
#include "intestine_measures.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "dmhs/whole_file.h"
#include "dmhs/liquid_state.h"

typedef struct {
  intestine_layout lay;
  PetscInt64 n_white0, n_red0;
  /* the rows from the wave's start on, for the measures at the end (replicated) */
  double *hist_t, *hist_x, *hist_a; /* t, x_F, alpha */
  PetscInt n_hist, cap_hist;
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
static PetscErrorCode intestine_open_csv(intestine_tracking *c, sim *s, double tw, double Tw,
                                         double delay) {
  const PetscInt np = c->lay.n_pockets;
  const size_t len = 512 + 32 * (size_t)(4 * np + 8);
  size_t at = 0;
  char *h;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(len, &h));
#define INTESTINE_HEADER(...) at += (size_t)snprintf(h + at, at < len ? len - at : 0, __VA_ARGS__)
  INTESTINE_HEADER(
      "# intestine: %" PetscInt_FMT " pockets, b %g m, dx %g m, level %g m, amplitude %g m, "
      "t_w %g s, T_w %g s, t_d %g s, fluid %" PetscInt64_FMT "\n",
      np, c->lay.b, c->lay.dx, c->lay.level, c->lay.amplitude, tw, Tw, delay, c->lay.n_fluid);
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
    PetscCheck(nw > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "intestine: no liquid in pocket 0 to track (the white set is empty)");
  }
  const double alpha = 1.0 - (double)cw[0] / (double)c->n_white0;
  double *lift;
  PetscCall(PetscMalloc1(np, &lift));
  for (PetscInt k = 0; k < np; k++) {
    seg_sel q = {c, k};
    PetscInt64 n;
    PetscCall(tracking_mean_displacement(s, intestine_segment_centre, &q, 1, &lift[k], &n));
    c->lift_max = PetscMax(c->lift_max, lift[k]);
  }
  const PetscInt sub = peristalsis_subperiod(c->lay.peri, s->t);
  /* the rows from the wave's start on (t, x_F, alpha), for the measures at the end */
  if (s->t >= delay - 0.5 * s->dt) {
    if (c->n_hist == c->cap_hist) {
      c->cap_hist = 2 * c->cap_hist + 64;
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_t));
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_x));
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_a));
    }
    c->hist_t[c->n_hist] = s->t;
    c->hist_x[c->n_hist] = xw;
    c->hist_a[c->n_hist++] = alpha;
  }
  if (s->rank == 0) { /* mpi: rank 0 writes */
    if (!c->csv)
      PetscCall(intestine_open_csv(c, s, tw, Tw, delay));
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

/* One row of <output_dir>/intestine-summary.csv: key, value (NAN: "n/a") and a
 * note (why a value is n/a, or how it was chosen; one CSV cell: written with a
 * comma as ';', a quote as ' and a newline as a blank). */
typedef struct {
  const char *key;
  double value;
  const char *note;
} summary_row;

/* <output_dir>/intestine-summary.csv (key,value,note), written to a temporary
 * name and renamed. */
static PetscErrorCode intestine_write_summary(sim *s, const summary_row *rows, PetscInt n) {
  char path[PETSC_MAX_PATH_LEN];
  whole_file w;
  PetscFunctionBeginUser;
  PetscCall(io_output_path(s, "intestine-summary.csv", path, sizeof(path)));
  PetscCall(whole_file_open(&w, path, NULL));
  FILE *f = w.f;
  int ok = fprintf(f, "key,value,note\n") > 0;
  for (PetscInt i = 0; i < n; i++) {
    char note[256];
    size_t k = 0;
    for (const char *c = rows[i].note; *c && k + 1 < sizeof(note); c++, k++)
      note[k] = *c == ',' ? ';' : *c == '"' ? '\'' : *c == '\n' ? ' ' : *c;
    note[k] = 0;
    ok = (isfinite(rows[i].value) ? fprintf(f, "%s,%.8g,%s\n", rows[i].key, rows[i].value, note)
                                  : fprintf(f, "%s,n/a,%s\n", rows[i].key, note)) > 0 &&
         ok;
  }
  PetscCall(whole_file_commit(&w, ok, NULL));
  PetscFunctionReturn(0);
}

/* "%.4g" of v (and its unit), or "n/a" */
static const char *intestine_num(char *buf, size_t len, double v) {
  if (isfinite(v))
    snprintf(buf, len, "%.4g", v);
  else
    snprintf(buf, len, "n/a");
  return buf;
}
static const char *intestine_speed(char *buf, size_t len, double v) {
  if (isfinite(v))
    snprintf(buf, len, "%.4g m/s", v);
  else
    snprintf(buf, len, "n/a");
  return buf;
}

static PetscErrorCode intestine_tracking_finish(diagnostic *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  intestine_tracking *c = self->data;
  const PetscInt n = c->n_hist;
  const double *t = c->hist_t, b = c->lay.b, nu = sp->nu;
  double tw, Tw, delay;
  PetscInt64 fluid, parked;
  char n1[32], n2[32], n3[32], n4[32], n5[32];
  PetscFunctionBeginUser;
  PetscCall(peristalsis_get(c->lay.peri, &tw, &Tw, NULL, NULL, &delay));
  /* a row lies within dt/2 of its output time (the driver's schedule) */
  const double tol = s->dt;
  intestine_front fr;
  PetscCall(intestine_measures_front(t, c->hist_x, n, delay, Tw, peristalsis_waves(c->lay.peri),
                                     c->lay.uf_initial_waves, c->lay.uf_r2_min, tol, &fr));
  /* the front's first advance: the slope while pocket 0 first squeezes (the
   * first contiguous rows with s_0 > 0) */
  double u_sq = NAN;
  {
    PetscInt i0 = -1, n0 = 0;
    for (PetscInt i = 0; i < n; i++)
      if (peristalsis_value(c->lay.peri, t[i], 0) > 0) {
        if (i0 < 0)
          i0 = i;
        if (i == i0 + n0)
          n0++;
      }
    if (i0 >= 0)
      PetscCall(tracking_slope(t + i0, c->hist_x + i0, n0, &u_sq));
  }
  /* alpha after one period, and at the end of the last whole wave */
  double t_aT, t_aE = NAN;
  const double aT = intestine_measures_at(t, c->hist_a, n, delay + Tw, tol, &t_aT);
  const double aE = fr.waves >= 1
                        ? intestine_measures_at(t, c->hist_a, n, delay + fr.waves * Tw, tol, &t_aE)
                        : NAN;
  PetscCall(intestine_fluid_counts(c, s, &fluid, &parked));
  double a_body[DMHS_DIM];
  body_force_at(c->lay.body, s->t, a_body);
  const double g = fabs(a_body[1]);
  const double Vw = c->lay.n_pockets * b / Tw;
  double uP, uS;
  char why_pump[96];
  intestine_measures_pumping(aT, Vw, c->lay.n_pockets, &uP, &uS, why_pump, sizeof(why_pump));
  const double Re = intestine_measures_reynolds(b, fr.u_F, nu);
  const double Re_P = intestine_measures_reynolds(b, uP, nu);
  const PetscBool measured = c->lift_max > c->lay.dx ? PETSC_TRUE : PETSC_FALSE;
  const double h = measured ? c->lift_max : c->lay.amplitude;
  const double Ga = h * h * h * g / (nu * nu), Fr = Vw / sqrt(g * h), Lambda = h / c->lay.level;

  /* why a value is n/a */
  char why_aT[128] = "", why_aE[128] = "", why_Re[128] = "", why_ReP[128] = "", why_sq[96] = "";
  const double t_last = n ? t[n - 1] : s->t;
  if (!isfinite(aT))
    PetscCall(PetscSNPrintf(why_aT, sizeof(why_aT),
                            "not reached: the rows end at %.6g s < t_d + T_w = %.6g s", t_last,
                            delay + Tw));
  if (!isfinite(aE))
    PetscCall(PetscSNPrintf(why_aE, sizeof(why_aE), "no whole wave"));
  if (!isfinite(fr.u_F))
    PetscCall(PetscSNPrintf(why_Re, sizeof(why_Re), "u_F undefined"));
  else if (!isfinite(Re))
    PetscCall(PetscSNPrintf(why_Re, sizeof(why_Re),
                            "u_F = %.4g m/s <= 0: the front did not advance", fr.u_F));
  if (!isfinite(uP))
    PetscCall(PetscSNPrintf(why_ReP, sizeof(why_ReP), "u_P undefined"));
  else if (!isfinite(Re_P))
    PetscCall(PetscSNPrintf(why_ReP, sizeof(why_ReP),
                            "u_P = 0: no tracked liquid out of pocket 0 after one period"));
  if (!isfinite(u_sq))
    PetscCall(PetscSNPrintf(why_sq, sizeof(why_sq), "pocket 0 squeezed in fewer than 2 rows"));

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
  PetscCall(PetscPrintf(s->comm,
                        "intestine: V_w = (N+1) b / T_w = %g m/s (T_w = %g s, t_w = %g s, "
                        "waves from t_d = %g s; %" PetscInt_FMT " whole in the rows)\n",
                        Vw, Tw, tw, delay, fr.waves));
  PetscCall(PetscPrintf(s->comm, "intestine: front velocity u_F = %s: %s\n",
                        intestine_speed(n1, sizeof(n1), fr.u_F), fr.why));
  if (fr.waves >= 1)
    PetscCall(PetscPrintf(s->comm,
                          "intestine:   least squares of x_F: over the %" PetscInt_FMT
                          " whole wave(s) %s (R^2 %s, t in [%g, %g] s, %" PetscInt_FMT " rows); "
                          "initial slope (first %" PetscInt_FMT
                          " wave(s)) %s (R^2 %s); first wave %s\n",
                          fr.waves, intestine_speed(n1, sizeof(n1), fr.line.slope),
                          intestine_num(n2, sizeof(n2), fr.line.r2), fr.line.t0, fr.line.t1,
                          fr.line.n, PetscMin(fr.waves, c->lay.uf_initial_waves),
                          intestine_speed(n3, sizeof(n3), fr.initial.slope),
                          intestine_num(n4, sizeof(n4), fr.initial.r2),
                          intestine_speed(n5, sizeof(n5), fr.first_wave.slope)));
  PetscCall(PetscPrintf(s->comm,
                        "intestine:   the front's first advance (while pocket 0 first squeezes) "
                        "u_F_squeeze = %s\n",
                        intestine_speed(n1, sizeof(n1), u_sq)));
  if (isfinite(aT))
    PetscCall(
        PetscPrintf(s->comm, "intestine: alpha after one period (row t = %g s) = %g", t_aT, aT));
  else
    PetscCall(PetscPrintf(s->comm, "intestine: alpha after one period: n/a (%s)", why_aT));
  if (isfinite(aE))
    PetscCall(PetscPrintf(s->comm, "; at the end of wave %" PetscInt_FMT " (row t = %g s) = %g\n",
                          fr.waves, t_aE, aE));
  else
    PetscCall(PetscPrintf(s->comm, "; at the last whole wave's end: n/a (%s)\n", why_aE));
  if (isfinite(uS))
    PetscCall(PetscPrintf(s->comm,
                          "intestine: u_P = alpha/(1-alpha) V_w/(N+1) = %s%s%s%s, u_S = alpha "
                          "V_w = %g m/s\n",
                          intestine_speed(n1, sizeof(n1), uP), isfinite(uP) ? "" : " (",
                          isfinite(uP) ? "" : why_pump, isfinite(uP) ? "" : ")", uS));
  else
    PetscCall(PetscPrintf(s->comm, "intestine: u_P, u_S: n/a (%s)\n", why_pump));
  PetscCall(
      PetscPrintf(s->comm,
                  "intestine: h = %g m (%s), Re = b u_F/nu = %s%s%s%s, Re_P = b u_P/nu = "
                  "%s%s%s%s, Ga = h^3 g/nu^2 = %g, Fr = V_w/sqrt(g h) = %g, Lambda = h/L = %g\n",
                  h,
                  measured ? "largest measured segment lift"
                           : "configured amplitude A: no lift above dx measured",
                  intestine_num(n1, sizeof(n1), Re), why_Re[0] ? " (" : "", why_Re,
                  why_Re[0] ? ")" : "", intestine_num(n2, sizeof(n2), Re_P), why_ReP[0] ? " (" : "",
                  why_ReP, why_ReP[0] ? ")" : "", Ga, Fr, Lambda));
  PetscCall(csv_close(&c->csv, "intestine.csv"));
  if (s->rank == 0) {
    summary_row rows[] = {
        {"b", b, ""},
        {"level", c->lay.level, ""},
        {"nu", nu, ""},
        {"t_w", tw, ""},
        {"t_d", delay, "the first wave's start"},
        {"T_w", Tw, ""},
        {"V_w", Vw, ""},
        {"waves", (double)fr.waves, "whole waves in the rows"},
        {"u_F", fr.u_F, ""},
        {"u_F_from_initial", isfinite(fr.u_F) ? (fr.from_initial ? 1.0 : 0.0) : NAN, ""},
        {"u_F_line", fr.line.slope, ""},
        {"u_F_line_r2", fr.line.r2, ""},
        {"u_F_line_x0", fr.line.x0, "the line's x_F at t_d"},
        {"u_F_line_t1", fr.waves >= 1 ? fr.line.t1 : NAN,
         "the line's window ends here (it starts at t_d)"},
        {"u_F_initial", fr.initial.slope, ""},
        {"u_F_initial_r2", fr.initial.r2, ""},
        {"u_F_initial_x0", fr.initial.x0, "the line's x_F at t_d"},
        {"u_F_initial_t1", fr.waves >= 1 ? fr.initial.t1 : NAN,
         "the line's window ends here (it starts at t_d)"},
        {"u_F_first_wave", fr.first_wave.slope, ""},
        {"u_F_squeeze", u_sq, ""},
        {"alpha_T", aT, ""},
        {"alpha_T_t", t_aT, "the row's time"},
        {"alpha_end", aE, ""},
        {"alpha_end_t", t_aE, "the row's time"},
        {"u_P", uP, ""},
        {"u_S", uS, ""},
        {"h", h, measured ? "largest measured segment lift" : "the haustral depth A"},
        {"Re", Re, ""},
        {"Re_P", Re_P, ""},
        {"Ga", Ga, ""},
        {"Fr", Fr, ""},
        {"Lambda", Lambda, ""},
        {"rho_dev_max", c->rho_dev_max, ""},
        {"mach_max", c->mach_max, ""},
        {"in_membrane_max", (double)c->inside_max, ""},
        {"through_max", (double)c->through_max, ""},
        {"fluid", (double)fluid, ""},
        {"overflow", (double)parked, ""},
        {"t_end", s->t, ""},
    };
    const PetscInt nrows = (PetscInt)(sizeof(rows) / sizeof(rows[0]));
    for (PetscInt i = 0; i < nrows; i++) {
      const char *k = rows[i].key, *why = NULL;
      if (!strcmp(k, "u_F") ||
          (!strncmp(k, "u_F_", 4) && strcmp(k, "u_F_squeeze") && !isfinite(rows[i].value)))
        why = fr.why;
      else if (!strcmp(k, "u_F_squeeze"))
        why = why_sq;
      else if (!strcmp(k, "alpha_T") || !strcmp(k, "alpha_T_t"))
        why = why_aT;
      else if (!strcmp(k, "alpha_end") || !strcmp(k, "alpha_end_t"))
        why = why_aE;
      else if ((!strcmp(k, "u_P") || !strcmp(k, "u_S")) && !isfinite(rows[i].value))
        why = why_pump;
      else if (!strcmp(k, "Re"))
        why = why_Re;
      else if (!strcmp(k, "Re_P"))
        why = why_ReP;
      if (why && why[0])
        rows[i].note = why;
    }
    PetscCall(intestine_write_summary(s, rows, nrows));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_checkpoint_write(diagnostic *self, sim *s,
                                                          checkpoint_io *io) {
  intestine_tracking *c = self->data;
  const PetscInt64 ints[5] = {c->n_white0, c->n_red0, c->n_hist, c->inside_max, c->through_max};
  const double reals[3] = {c->lift_max, c->rho_dev_max, c->mach_max};
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "intestine_ints", ints, 5));
  PetscCall(checkpoint_put_reals(io, "intestine_reals", reals, 3));
  if (c->n_hist) {
    PetscCall(checkpoint_put_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_put_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
    PetscCall(checkpoint_put_reals(io, "intestine_hist_alpha", c->hist_a, c->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_tracking_checkpoint_read(diagnostic *self, sim *s,
                                                         checkpoint_io *io) {
  intestine_tracking *c = self->data;
  PetscInt64 ints[5];
  double reals[3];
  PetscInt n_alpha;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_get_ints(io, "intestine_ints", ints, 5));
  /* a checkpoint whose history covers the first wave only (no alpha rows) cannot give
   * the measures over the whole run */
  PetscCall(checkpoint_get_length(io, "intestine_hist_alpha", &n_alpha));
  PetscCheck(ints[2] == 0 || n_alpha == ints[2], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "the checkpoint's intestine history has no alpha rows: it was written by a dmhs "
             "that kept x_F over the first wave only; continue it with that version");
  PetscCall(checkpoint_get_reals(io, "intestine_reals", reals, 3));
  c->n_white0 = ints[0];
  c->n_red0 = ints[1];
  c->n_hist = c->cap_hist = (PetscInt)ints[2];
  c->lift_max = reals[0];
  c->rho_dev_max = reals[1];
  c->mach_max = reals[2];
  c->inside_max = ints[3];
  c->through_max = ints[4];
  PetscCall(PetscFree(c->hist_t));
  PetscCall(PetscFree(c->hist_x));
  PetscCall(PetscFree(c->hist_a));
  if (c->n_hist) {
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_t));
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_x));
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_a));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_alpha", c->hist_a, c->n_hist));
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
  PetscCall(PetscFree(c->hist_a));
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
