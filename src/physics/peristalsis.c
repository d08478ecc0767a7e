/* Module peristalsis: the peristaltic wave on the intestine's
 * membrane segments, and the support that holds the membrane in shape.
 *
 * Time after -peristalsis_delay t_d is cut into sub-periods of t_w; sub-period
 * r = floor((t - t_d)/t_w) mod R of a wave of R rows (R = 2N + 5 generated,
 * or the rows of -peristalsis_schedule FILE). The schedule S[r][k] in
 * {-1, 0, +1} (generated: -1 for r = 2k-1, +1 for r = 2k+1 .. 2k+H, mod R)
 * pushes every solid particle i of pocket k's segment (segment PERISTALSIS_SEGMENT0 + k)
 *   a_i += S[r][k] F w(x0_i) / m_i  (along +y),  w = sin^2(pi (x0 - x_k)/b),
 * a smooth bump that vanishes at the folds between pockets, so neighbouring
 * segments pushed opposite ways do not tear the bonds at the fold.
 * The support (the Dynamic Colon Model's frame; without it the liquid's
 * weight would sag the soft membrane by decimetres) acts on every solid:
 *   a_i += -k_s (x_i - x0_i)/m_i - gamma v_i.
 * The schedule value switches between sub-periods along a smoothstep
 * 3u^2 - 2u^3 over the first -peristalsis_ramp fraction of each sub-period
 * (an abrupt switch would fling the membrane faster than the sound speed).
 * A static segment then lifts by about F/k_s at its centre (less the bonds'
 * tension and the liquid's weight): the calibration note in doc/guide/scene-intestine.md.
 * The state (current sub-period) is a function of t alone, so restarts need
 * no private checkpoint data. */
#include <math.h>
#include <errno.h>
#include <string.h>
#include <ctype.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/fields.h"
#include "dmhs/peristalsis.h"
#include "dmhs/events.h"
#include "dmhs/sph.h"
#include "dmhs/bond.h"

typedef struct {
  PetscInt n_pockets; /* N + 1 */
  double b, x_left;   /* pocket length, left end of pocket 0 [m] */
  double t_w;         /* sub-period [s] */
  PetscInt H;         /* squeezing sub-periods */
  PetscInt waves;     /* 0 = repeat to the end */
  double delay;       /* [s] before the first wave */
  double force;       /* F per particle [N] */
  double support;     /* k_s per particle [N/m] */
  double damping;     /* gamma [1/s] */
  double ramp;        /* switching time as a fraction of t_w */
  char file[PETSC_MAX_PATH_LEN];
  PetscInt rows;  /* R */
  signed char *S; /* R x n_pockets */
  PetscInt n_seg; /* tagged solids over all ranks */
  double m_min;   /* the smallest solid mass over all ranks, at setup (masses stay) */
} peri_data;

int peristalsis_spec_value(PetscInt n_pockets, PetscInt H, PetscInt r, PetscInt k) {
  const PetscInt R = 2 * (n_pockets - 1) + 5;
  const PetscInt down = ((2 * k - 1) % R + R) % R, up = (((r - 2 * k - 1) % R) + R) % R;
  if (r == down)
    return -1;
  if (up < H)
    return 1;
  return 0;
}

PetscErrorCode peristalsis_set_geometry(module *m, PetscInt n_pockets, double b, double x_left) {
  peri_data *d = m->data;
  PetscFunctionBeginUser;
  d->n_pockets = n_pockets;
  d->b = b;
  d->x_left = x_left;
  PetscFunctionReturn(0);
}

PetscInt peristalsis_subperiod(const module *m, double t) {
  const peri_data *d = m->data;
  if (t < d->delay || d->rows == 0)
    return -1;
  /* the step's t = step dt carries round-off: a boundary hit within 1e-9 t_w counts as the later
   * sub-period */
  const double u = (t - d->delay) / d->t_w + 1e-9;
  const PetscInt64 n = (PetscInt64)floor(u);
  if (d->waves > 0 && n >= (PetscInt64)d->waves * d->rows)
    return -1;
  return (PetscInt)(n % d->rows);
}

int peristalsis_value(const module *m, double t, PetscInt k) {
  const peri_data *d = m->data;
  const PetscInt r = peristalsis_subperiod(m, t);
  if (r < 0 || k < 0 || k >= d->n_pockets)
    return 0;
  return d->S[r * d->n_pockets + k];
}

double peristalsis_amplitude(const module *m, double t, PetscInt k) {
  const peri_data *d = m->data;
  const double now = peristalsis_value(m, t, k);
  if (d->ramp <= 0 || t < d->delay)
    return now;
  const double u = fmod((t - d->delay) / d->t_w + 1e-9, 1.0) / d->ramp;
  if (u >= 1)
    return now;
  const double before = peristalsis_value(m, t - d->t_w, k), w = u * u * (3 - 2 * u);
  return before + (now - before) * w;
}

PetscErrorCode peristalsis_get(const module *m, double *t_w, double *T_w, PetscInt *H,
                               PetscInt *rows, double *delay) {
  const peri_data *d = m->data;
  PetscFunctionBeginUser;
  if (t_w)
    *t_w = d->t_w;
  if (T_w)
    *T_w = d->rows * d->t_w;
  if (H)
    *H = d->H;
  if (rows)
    *rows = d->rows;
  if (delay)
    *delay = d->delay;
  PetscFunctionReturn(0);
}

PetscInt peristalsis_waves(const module *m) {
  const peri_data *d = m->data;
  return d->waves;
}

static PetscErrorCode peristalsis_set_from_options(module *self, sim *s) {
  peri_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(fields_enable("segment")); /* which pocket's wave moves a membrane particle */
  PetscCall(fields_enable("x0"));      /* the supports' anchors */
  PetscOptionsBegin(s->comm, NULL, "Peristaltic wave on the membrane segments (module peristalsis)",
                    NULL);
  PetscCall(options_read_real("-peristalsis_tw", "Sub-period t_w [s]; wave period T_w = (2N+5) t_w",
                              NULL, d->t_w, &d->t_w, NULL));
  PetscCall(options_read_int("-peristalsis_h",
                             "Squeezing sub-periods H (2 = original wave, 5 = new wave) [1]", NULL,
                             d->H, &d->H, NULL));
  PetscCall(options_read_int("-peristalsis_waves", "Number of waves (0 = repeat until -t_end) [1]",
                             NULL, d->waves, &d->waves, NULL));
  PetscCall(options_read_real("-peristalsis_delay",
                              "Time before the first wave (the liquid settles) [s]", NULL, d->delay,
                              &d->delay, NULL));
  PetscCall(options_read_real("-peristalsis_force",
                              "Wave force F per membrane particle at a segment's centre [N]", NULL,
                              d->force, &d->force, NULL));
  PetscCall(options_read_real(
      "-peristalsis_support",
      "Support spring k_s per membrane particle towards its initial position [N/m]", NULL,
      d->support, &d->support, NULL));
  PetscCall(options_read_real("-peristalsis_damping",
                              "Damping rate gamma on membrane particles [1/s]", NULL, d->damping,
                              &d->damping, NULL));
  PetscCall(options_read_real(
      "-peristalsis_ramp",
      "Switching time of the force between sub-periods, fraction of t_w (smoothstep) [1]", NULL,
      d->ramp, &d->ramp, NULL));
  PetscCall(options_read_string(
      "-peristalsis_schedule",
      "File of the 0/+1/-1 schedule: one row per sub-period, one column per pocket", NULL, d->file,
      d->file, sizeof(d->file), NULL));
  PetscOptionsEnd();
  PetscCheck(d->t_w > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_tw must be > 0 (got %g s)", d->t_w);
  PetscCheck(d->H >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_h must be >= 1 (got %" PetscInt_FMT ")", d->H);
  PetscCheck(d->waves >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_waves must be >= 0 (got %" PetscInt_FMT ")", d->waves);
  PetscCheck(d->delay >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_delay must be >= 0 s (got %g)", d->delay);
  PetscCheck(d->ramp >= 0 && d->ramp <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_ramp must lie in [0, 1] (got %g)", d->ramp);
  PetscCheck(d->support >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_support must be >= 0 N/m (got %g)", d->support);
  PetscCheck(d->damping >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-peristalsis_damping must be >= 0 1/s (got %g)", d->damping);
  PetscFunctionReturn(0);
}

/* Reads the schedule file: '#' starts a comment, blank lines are skipped,
 * values separated by blanks or commas, each -1, 0 or 1, n_pockets per row. */
static PetscErrorCode peristalsis_read_file(peri_data *d, MPI_Comm comm) {
  FILE *f = fopen(d->file, "r");
  char line[4096];
  PetscInt cap = 64, rows = 0, lineno = 0;
  signed char *S;
  PetscFunctionBeginUser;
  PetscCheck(f, comm, PETSC_ERR_FILE_OPEN, "-peristalsis_schedule %s: cannot open: %s", d->file,
             strerror(errno));
  PetscCall(PetscMalloc1(cap * d->n_pockets, &S));
  while (fgets(line, sizeof(line), f)) {
    lineno++;
    char *c = strchr(line, '#');
    if (c)
      *c = 0;
    PetscInt n = 0;
    char *p = line;
    for (;;) {
      while (*p && (isspace((unsigned char)*p) || *p == ','))
        p++;
      if (!*p)
        break;
      char *end;
      const long v = strtol(p, &end, 10);
      const PetscBool ok = end != p && (v == -1 || v == 0 || v == 1) &&
                           (!*end || isspace((unsigned char)*end) || *end == ',');
      if (!ok)
        fclose(f);
      PetscCheck(ok, comm, PETSC_ERR_FILE_UNEXPECTED,
                 "-peristalsis_schedule %s:%" PetscInt_FMT ": value %" PetscInt_FMT
                 " is not -1, 0 or 1",
                 d->file, lineno, n + 1);
      if (n < d->n_pockets) {
        if (rows == cap) {
          signed char *T;
          PetscCall(PetscMalloc1(2 * cap * d->n_pockets, &T));
          PetscCall(PetscArraycpy(T, S, cap * d->n_pockets));
          PetscCall(PetscFree(S));
          S = T;
          cap *= 2;
        }
        S[rows * d->n_pockets + n] = (signed char)v;
      }
      n++;
      p = end;
    }
    if (n == 0)
      continue;
    if (n != d->n_pockets)
      fclose(f);
    PetscCheck(n == d->n_pockets, comm, PETSC_ERR_FILE_UNEXPECTED,
               "-peristalsis_schedule %s:%" PetscInt_FMT ": %" PetscInt_FMT
               " values, expected one per pocket (%" PetscInt_FMT ")",
               d->file, lineno, n, d->n_pockets);
    rows++;
  }
  fclose(f);
  PetscCheck(rows > 0, comm, PETSC_ERR_FILE_UNEXPECTED, "-peristalsis_schedule %s: no rows",
             d->file);
  d->S = S;
  d->rows = rows;
  PetscFunctionReturn(0);
}

static PetscErrorCode peristalsis_setup(module *self, sim *s) {
  peri_data *d = self->data;
  PetscInt local = 0;
  PetscFunctionBeginUser;
  PetscCheck(d->n_pockets > 0 && d->b > 0, s->comm, PETSC_ERR_ORDER,
             "peristalsis: the scene must call peristalsis_set_geometry");
  PetscCall(PetscFree(d->S));
  if (d->file[0])
    PetscCall(peristalsis_read_file(d, s->comm));
  else {
    d->rows = 2 * (d->n_pockets - 1) + 5;
    PetscCall(PetscMalloc1(d->rows * d->n_pockets, &d->S));
    for (PetscInt r = 0; r < d->rows; r++)
      for (PetscInt k = 0; k < d->n_pockets; k++)
        d->S[r * d->n_pockets + k] = (signed char)peristalsis_spec_value(d->n_pockets, d->H, r, k);
  }
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    local += s->ps.type[i] == PTYPE_SOLID && s->ps.segment[i] >= PERISTALSIS_SEGMENT0 &&
             s->ps.segment[i] < PERISTALSIS_SEGMENT0 + d->n_pockets;
  PetscCallMPI(MPI_Allreduce(&local, &d->n_seg, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscCall(bond_min_solid_mass(s, &d->m_min)); /* for the support's limit, every step */
  PetscFunctionReturn(0);
}

static PetscErrorCode peristalsis_compute(module *self, sim *s) {
  const peri_data *d = self->data;
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.peristalsis, 0, 0, 0, 0));
  const PetscInt np = d->n_pockets;
  double *amp; /* per pocket: S[r][k] blended with S[r-1][k] over the ramp */
  PetscCall(PetscMalloc1(np, &amp));
  for (PetscInt k = 0; k < np; k++)
    amp[k] = peristalsis_amplitude(self, s->t, k);
  const double F = d->force, ks = d->support, g = d->damping, inv_b = 1.0 / d->b, xl = d->x_left;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_SOLID)
      continue;
    const double im = 1.0 / ps->mass[i];
    ps->a[i][0] -= ks * (ps->x[i][0] - ps->x0[i][0]) * im + g * ps->v_est[i][0];
    ps->a[i][1] -= ks * (ps->x[i][1] - ps->x0[i][1]) * im + g * ps->v_est[i][1];
    const PetscInt k = ps->segment[i] - PERISTALSIS_SEGMENT0;
    if (k < 0 || k >= np || amp[k] == 0)
      continue;
    const double sn = sin(M_PI * (ps->x0[i][0] - xl - k * d->b) * inv_b);
    ps->a[i][1] += amp[k] * F * sn * sn * im;
  }
  PetscCall(PetscFree(amp));
  PetscCall(PetscLogFlops(12.0 * (double)ps->n_owned));
  PetscCall(PetscLogEventEnd(events.peristalsis, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode peristalsis_max_dt(module *self, sim *s, dt_limits *l) {
  const peri_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s; /* the smallest mass is taken at setup */
  const double m = d->m_min;
  if (d->support > 0 && isfinite(m))
    PetscCall(
        dt_limits_add(l, "peristalsis support", "0.2 sqrt(m/k_s)", 0.2 * sqrt(m / d->support)));
  if (d->damping > 0)
    PetscCall(dt_limits_add(l, "peristalsis damping", "0.2/gamma", 0.2 / d->damping));
  PetscFunctionReturn(0);
}

/* Pre-flight: the membrane's peak speed under the wave, against the liquid's sound
 * speed. A segment lifts by about F/k_s within the smoothstep's switching time
 * ramp t_w, at up to U_m = 1.5 (F/k_s)/(ramp t_w); the liquid the wave squeezes out
 * and throws off moves at up to ~3 U_m (measured 2.7 U_m for the study's fastest
 * wave, doc/validation.md "Intestine"), so Mach <= 0.1 asks c0 >= 30 U_m. A warning,
 * not an error: the estimate comes from one measured case. */
static PetscErrorCode peristalsis_preflight(module *self, sim *s, int *problems) {
  const peri_data *d = self->data;
  PetscFunctionBeginUser;
  (void)problems;
  if (d->ramp <= 0 || d->support <= 0 || !sim_find_module(s, "sph"))
    PetscFunctionReturn(0);
  const double u_m = 1.5 * (d->force / d->support) / (d->ramp * d->t_w);
  const double c0 = sph_params_get(s)->c0, need = 30.0 * u_m;
  PetscCall(PetscPrintf(s->comm,
                        "  %-18s U_m = 1.5 (F/k_s)/(ramp t_w) = %.3g m/s: the liquid it throws "
                        "reaches ~3 U_m; Mach <= 0.1 asks c0 >= 30 U_m = %.3g m/s (c0 = %.3g)%s\n",
                        "membrane speed", u_m, need, c0, c0 < need ? "  LOW" : ""));
  if (c0 < need)
    PetscCall(
        PetscPrintf(s->comm,
                    "WARNING: -sph_c0 %.3g m/s is below 30 U_m = %.3g m/s for this wave: expect "
                    "Mach > 0.1 (raise -sph_c0; measured for the fastest wave of the study: "
                    "-sph_c0 15 -sph_av_alpha 0.1, doc/validation.md)\n",
                    c0, need));
  PetscFunctionReturn(0);
}

static PetscErrorCode peristalsis_view(module *self, sim *s, PetscViewer v) {
  const peri_data *d = self->data;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "peristalsis: %" PetscInt_FMT
                                   " pockets of b = %g m, t_w = %g s, %s schedule of %" PetscInt_FMT
                                   " rows (T_w = %g s, H = %" PetscInt_FMT "), waves %" PetscInt_FMT
                                   " (0 = until t_end), delay %g s\n"
                                   "  force %g N per particle on %" PetscInt_FMT
                                   " segment particles, support %g N/m, damping %g 1/s\n",
                                   d->n_pockets, d->b, d->t_w, d->file[0] ? d->file : "generated",
                                   d->rows, d->rows * d->t_w, d->H, d->waves, d->delay, d->force,
                                   d->n_seg, d->support, d->damping));
  PetscFunctionReturn(0);
}

static PetscErrorCode peristalsis_destroy(module *self) {
  peri_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(d->S));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode peristalsis_module_create(module **m) {
  peri_data *d;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  PetscCall(PetscNew(&d));
  d->t_w = 0.3;
  d->H = 2;
  d->force = 1.0;
  d->support = 100.0;
  d->damping = 1000.0;
  d->ramp = 1.0;
  (*m)->name = "peristalsis";
  (*m)->set_from_options = peristalsis_set_from_options;
  (*m)->setup = peristalsis_setup;
  (*m)->preflight = peristalsis_preflight;
  (*m)->compute = peristalsis_compute;
  (*m)->max_dt = peristalsis_max_dt;
  (*m)->view = peristalsis_view;
  (*m)->destroy = peristalsis_destroy;
  (*m)->data = d;
  PetscFunctionReturn(0);
}
