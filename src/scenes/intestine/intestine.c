/* Scene intestine: the Dynamic Colon Model, a 2D channel of N + 1
 * pockets (haustra) of length b on a lower membrane only, partly filled with
 * liquid, squeezed by a peristaltic wave (module peristalsis).
 *
 * Geometry (x along the colon, y up; pocket k spans [k b, (k+1) b], so the
 * published centre x_k = k b is measured from -b/2 here):
 *   membrane: 3 layers (-intestine_membrane_layers) of bonded MSM + SPH
 *     particles; the top layer follows the haustral profile
 *       y_s(x) = -A sin^2(pi x / b)   (A = -intestine_amplitude),
 *     columns spaced r0 = dx along the middle layer's arc, the other layers
 *     offset by r0 along its normal; the first and last -intestine_clamp
 *     columns (default: those within b/25 of each end) are fixed (wall
 *     particles): the membrane cannot drift;
 *   liquid: the lattice (i + 1/2) dx above the membrane up to the level y = L
 *     (-intestine_level, above the folds y = 0, where pockets meet);
 *   a wall closes the left end (x < 0), up to L + -intestine_wall_height;
 *   a weir closes the right end (x > (N+1) b) up to y = -intestine_weir
 *     (default L): liquid that rises over it passes x = (N+1) b and counts as
 *     pocket N + 1; beyond the weir it is parked (turned into a fixed,
 *     isolated particle in a parking lot right of the channel, one slot per
 *     fluid gid), never lost: "overflow" in the CSV and the final report.
 * Tracked sets: the liquid initially in pocket 0 ("white", tracer 1) and, with
 * -intestine_red, in pocket -intestine_red_pocket ("red", tracer 2).
 *
 * Diagnostics: "intestine" (intestine.csv at output times, the summary at the
 * end: src/scenes/intestine/intestine_tracking.c). After every step the liquid past the
 * weir is parked (intestine_post_step). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/body_force.h"
#include "dmhs/peristalsis.h"
#include "dmhs/tracking.h"
#include "intestine_tracking.h"

typedef struct {
  PetscInt n_pockets; /* N + 1 */
  double b, dx, level, amplitude, wall_height, weir;
  PetscInt layers, clamp, red_pocket;
  PetscBool red;
  double uf_r2_min; /* the measures' u_F rule (intestine_measures.h) */
  PetscInt uf_initial_waves;
  module *body, *rep, *peri;
  PetscInt64 n_fluid;   /* fluid gids 0 .. n_fluid - 1 */
  double x_end, x_park; /* (N+1) b; parking line past the weir */
  double lot_x0, lot_y0, lot_sp;
  PetscInt lot_rows;
} intestine_data;

static PetscErrorCode intestine_set_from_options(scene *self, sim *s) {
  intestine_data *c = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene intestine (colon with peristalsis)", NULL);
  PetscCall(options_read_int("-intestine_pockets", "Number of pockets N + 1 [1]", NULL,
                             c->n_pockets, &c->n_pockets, NULL));
  PetscCall(options_read_real("-intestine_b", "Pocket length b [m]", NULL, c->b, &c->b, NULL));
  PetscCall(options_read_real("-intestine_dx", "Particle spacing dx [m] (also the membrane's r0)",
                              NULL, c->dx, &c->dx, NULL));
  PetscCall(options_read_real("-intestine_level", "Liquid level L above the folds [m]", NULL,
                              c->level, &c->level, NULL));
  PetscCall(options_read_real("-intestine_amplitude",
                              "Haustral depth A of the profile -A sin^2(pi x/b) [m]", NULL,
                              c->amplitude, &c->amplitude, NULL));
  PetscCall(options_read_int("-intestine_membrane_layers", "Membrane particle layers [1]", NULL,
                             c->layers, &c->layers, NULL));
  /* the columns within b/25 of each end (3 at dx = 2.5e-4 m, 1 at 5e-4 m): the wave's bump
   * F sin^2(pi x/b) at the first free column, ~ F (pi x/b)^2, is what the membrane's step from
   * the fixed column to the free one has to take; a clamp of 1.5 mm at dx = 5e-4 m (0.07 F
   * there) let the lowered membrane open a gap at its edge, and liquid went through it
   * (doc/validation.md, "Seven waves"). Guarded and capped: b and dx are checked below, after
   * the options are read, and the cast must be defined for any dx. */
  const double within = c->b > 0 && c->dx > 0 ? floor(c->b / (25.0 * c->dx) + 1e-9) : 1.0;
  c->clamp = PetscMax(1, (PetscInt)PetscMin(within, 1e6));
  PetscCall(options_read_int("-intestine_clamp",
                             "Fixed membrane columns at each end [1] (default: those within b/25)",
                             NULL, c->clamp, &c->clamp, NULL));
  PetscCall(options_read_real("-intestine_wall_height", "Left wall's height above the level [m]",
                              NULL, c->wall_height, &c->wall_height, NULL));
  c->weir = c->level;
  PetscCall(options_read_real("-intestine_weir",
                              "Top of the overflow weir above the folds [m] (default: the level)",
                              NULL, c->weir, &c->weir, NULL));
  PetscCall(options_read_bool("-intestine_red", "Track the liquid of a second pocket (red)", NULL,
                              c->red, &c->red, NULL));
  PetscCall(options_read_int("-intestine_red_pocket", "Pocket of the red set [1]", NULL,
                             c->red_pocket, &c->red_pocket, NULL));
  PetscCall(options_read_real("-intestine_uf_r2_min",
                              "u_F: the least-squares line of x_F over the whole waves fits when "
                              "its R^2 reaches this, else u_F is the initial slope [1]",
                              NULL, c->uf_r2_min, &c->uf_r2_min, NULL));
  PetscCall(options_run_control("-intestine_uf_r2_min"));
  PetscCall(options_read_int("-intestine_uf_initial_waves",
                             "u_F's initial slope: the line over the first this many waves [1]",
                             NULL, c->uf_initial_waves, &c->uf_initial_waves, NULL));
  PetscCall(options_run_control("-intestine_uf_initial_waves"));
  PetscOptionsEnd();
  PetscCheck(c->uf_r2_min > 0 && c->uf_r2_min <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_uf_r2_min must lie in (0, 1] (got %g)", c->uf_r2_min);
  PetscCheck(c->uf_initial_waves >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_uf_initial_waves must be >= 1 (got %" PetscInt_FMT ")",
             c->uf_initial_waves);
  PetscCheck(c->n_pockets >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_pockets must be >= 1 (got %" PetscInt_FMT ")", c->n_pockets);
  PetscCheck(c->b > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-intestine_b must be > 0 m (got %g)",
             c->b);
  PetscCheck(c->dx > 0 && c->dx < 0.1 * c->b, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_dx must lie in (0, %g) m (a tenth of -intestine_b; got %g)", 0.1 * c->b,
             c->dx);
  PetscCheck(c->level > c->dx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_level must exceed -intestine_dx = %g m (got %g)", c->dx, c->level);
  PetscCheck(c->amplitude >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_amplitude must be >= 0 m (got %g)", c->amplitude);
  PetscCheck(c->wall_height >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_wall_height must be >= 0 m (got %g)", c->wall_height);
  PetscCheck(c->weir >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_weir must be >= 0 m (got %g)", c->weir);
  PetscCheck(c->layers >= 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_membrane_layers must be >= 2 (got %" PetscInt_FMT ")", c->layers);
  PetscCheck(c->clamp >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_clamp must be >= 1 (got %" PetscInt_FMT ")", c->clamp);
  PetscCheck(!c->red || (c->red_pocket > 0 && c->red_pocket < c->n_pockets), s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_red_pocket must lie in [1, N] (got %" PetscInt_FMT ")", c->red_pocket);
  s->dx = c->dx;
  /* the published case; h = 2.5 dx, not the published h = dx (no neighbour inside the support) */
  module *sph;
  PetscCall(modules_enable(s, "sph", &sph));
  sph_params *sp = sph_defaults(sph);
  /* c0 = 5 m/s, not the published 1 m/s (doc/validation.md, "Intestine"):
   * at 1 m/s (B = 143 Pa) the hydrostatic pressure of the 7.6 mm deep pockets
   * alone compresses the liquid by 5.7 %, and the pouring liquid reaches
   * 0.2-0.4 m/s (Mach 0.2-0.4); 5 m/s keeps both within 1 % and 0.1;
   * nu = 1e-5 lies inside the published 0.5e-6 ... 500e-6 m^2/s, quieter than water's 1e-6 */
  PetscCall(sph_set_liquid(sph, 2.5 * c->dx, 1000.0, 5.0, 1e-5)); /* h, rho0, c0, nu */
  /* density diffusion: without it the liquid at rest on the membrane is
   * unstable (continuity density at cell Reynolds number c0 h/nu ~ 600:
   * at c0 = 5 m/s Mach 0.5 after 0.05 s with no wave, at 1 m/s Mach 0.17
   * after 0.12 s); with delta = 0.1 it stays at Mach 0.004 (doc/theory.md) */
  sp->delta = 0.1;
  /* the density predicted for the end of the step, as in the vein: with the half-step
   * density a liquid particle ringing against membrane or wall particles (where the
   * diffusion above does not act) grows at omega^2 dt/4, and a faster sound speed makes
   * it worse (the PET miniature at c0 = 10 m/s: 4.8 % by 1 s, 0.18 % with this;
   * doc/validation.md, "Intestine") */
  sp->density_predict = PETSC_TRUE;
  PetscCall(fields_enable("tracer")); /* the white (and red) liquid */
  PetscCall(fields_enable("x0"));     /* tracking's displacements, the segments' centres */
  PetscCall(modules_enable(s, "body_force", &c->body));
  PetscCall(body_force_set_default_gravity(c->body, 9.81));
  /* the published membrane is nonlinear (FENE-like) */
  PetscCall(solid_modules_enable(s, BOND_NONLINEAR));
  /* k_b = 1e-4 J, r0 = dx, r_max = 1.8 dx (4.5e-4 m at dx = 2.5e-4 m) */
  PetscCall(bond_set_default(s, 1e-4, c->dx, 1.8 * c->dx));
  PetscCall(angle_set_default(s, 8e-5, 90.0));
  PetscCall(modules_enable(s, "repulsion", &c->rep));
  /* K = 8000 J/m^2 x dx^2 (2e-3 J at dx = 5e-4 m, 5e-4 J at the study's
   * 2.5e-4 m), not the published 1e-10 J (doc/validation.md, "Intestine"):
   * where the wave stretches the membrane to ~1.9 r0, a liquid particle in a
   * gap between two membrane particles is 0.95 r* from both, where the SPH
   * pressure force vanishes (dW/dr -> 0) and 1e-10 J pushes ~1e-7 N/m against
   * the liquid's p dx ~ 0.05 N/m: the liquid went through (half this K still
   * let it through near a clamped end). The repulsion's limit, 0.035 dx
   * [s/m], binds dt: 1.8x below the sound speed's at c0 = 5 m/s. */
  PetscCall(repulsion_set_default(c->rep, 8000.0 * c->dx * c->dx, c->dx, 4, 2));
  PetscCall(modules_enable(s, "peristalsis", &c->peri));
  PetscCall(peristalsis_set_geometry(c->peri, c->n_pockets, c->b, 0.0));
  PetscFunctionReturn(0);
}

static inline double intestine_profile(const intestine_data *c, double x) {
  const double sn = sin(M_PI * x / c->b);
  return -c->amplitude * sn * sn;
}
static inline double intestine_slope(const intestine_data *c, double x) {
  return -c->amplitude * M_PI / c->b * sin(2.0 * M_PI * x / c->b);
}

static PetscErrorCode intestine_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  intestine_data *c = self->data;
  const double dx = c->dx, m = sp->rho0 * dx * dx, zero[2] = {0, 0};
  const PetscInt wl = (PetscInt)ceil(sp->h / dx - 1e-9); /* wall layers filling the support */
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  c->x_end = c->n_pockets * c->b;
  double a_body[DMHS_DIM]; /* the hydrostatic start's g: the body force's downward part */
  body_force_at(c->body, 0.0, a_body);
  const double g = -a_body[1];
  const double y_bottom = -c->amplitude - c->layers * dx; /* lowest membrane particle, about */
  const double y_top = c->level + c->wall_height;
  s->dom.lo[0] = -(wl + 2) * dx;
  s->dom.lo[1] = y_bottom - 0.02 - 2 * dx; /* room for the membrane pushed down */
  s->dom.hi[1] = y_top + 0.02;
  s->dom.periodic[0] = s->dom.periodic[1] = PETSC_FALSE;
  /* parked as it passes the centre of the weir's inner column, i.e. once it is
   * over the weir (doc/validation.md, "Intestine"): a film that clung to the
   * outer face crept under the weir and the membrane, and a lone particle
   * left on the crest, its pressure extrapolated to the wall from itself
   * alone, rattled up to Mach 0.23 */
  c->x_park = c->x_end + 0.5 * dx;
  c->lot_sp = 2.2 * sp->h;
  c->lot_x0 = c->x_park + 2 * c->lot_sp;
  c->lot_y0 = s->dom.lo[1] + c->lot_sp;
  c->lot_rows = (PetscInt)floor((s->dom.hi[1] - s->dom.lo[1] - 2 * c->lot_sp) / c->lot_sp);
  PetscCheck(c->lot_rows > 0, s->comm, PETSC_ERR_PLIB, "intestine: no room for the parking lot");
  /* liquid (gids 0 .. n_fluid - 1) */
  const PetscInt nx = (PetscInt)floor(c->x_end / dx + 1e-9);
  const PetscInt j0 = (PetscInt)floor((-c->amplitude) / dx) - 1,
                 j1 = (PetscInt)ceil(c->level / dx) + 1;
  for (PetscInt i = 0; i < nx; i++)
    for (PetscInt j = j0; j <= j1; j++) {
      const double x[2] = {(i + 0.5) * dx, (j + 0.5) * dx};
      const double ys = intestine_profile(c, x[0]), sl = intestine_slope(c, x[0]);
      if (x[1] >= c->level || x[1] < ys + 0.95 * dx * sqrt(1 + sl * sl))
        continue;
      /* hydrostatic start, rho from p = rho0 g (L - y) through the Tait EOS: no collapse under
       * gravity */
      const double B = sp->c0 * sp->c0 * sp->rho0 / 7.0, ph = sp->rho0 * g * (c->level - x[1]);
      const double rho =
          sp->eos == SPH_EOS_TAIT ? sp->rho0 * pow(1.0 + ph / B, 1.0 / 7.0) : sp->rho0;
      PetscInt idx;
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, zero, m, rho, &idx));
      const PetscInt k = tracking_pocket(x[0], c->n_pockets, c->b, 0.0);
      if (k == 0)
        s->ps.tracer[idx] = INTESTINE_TRACER_WHITE;
      else if (c->red && k == c->red_pocket)
        s->ps.tracer[idx] = INTESTINE_TRACER_RED;
    }
  c->n_fluid = gid;
  /* the parking lot must fit in x: widen the domain */
  const PetscInt lot_cols = (PetscInt)((c->n_fluid + c->lot_rows - 1) / c->lot_rows);
  s->dom.hi[0] = c->lot_x0 + (lot_cols + 1) * c->lot_sp;
  /* left wall and right weir: wl columns from below the membrane's end up */
  const PetscInt jb = (PetscInt)floor(-c->layers * dx / dx) - 1;
  for (PetscInt k = 0; k < wl; k++) {
    for (PetscInt j = jb; (j + 0.5) * dx < y_top; j++) {
      const double x[2] = {-(k + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, x, zero, m, sp->rho0, NULL));
    }
    for (PetscInt j = jb; (j + 0.5) * dx < c->weir; j++) {
      const double x[2] = {c->x_end + (k + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, x, zero, m, sp->rho0, NULL));
    }
  }
  /* membrane: middle-line arc y_m(x) = y_s(x) - (layers-1)/2 dx, columns every dx of arc */
  const double off = 0.5 * (c->layers - 1) * dx;
  double *cx;
  PetscInt ncol = 0, cap = (PetscInt)(4 * c->x_end / dx) + 16;
  PetscCall(PetscMalloc1(cap, &cx));
  {
    double x = 0.5 * dx, arc = 0;
    const double step = dx / 64;
    cx[ncol++] = x;
    while (x < c->x_end - 0.5 * dx) {
      const double sl = intestine_slope(c, x + 0.5 * step);
      arc += step * sqrt(1 + sl * sl);
      x += step;
      if (arc >= dx) {
        PetscCheck(ncol < cap, s->comm, PETSC_ERR_PLIB, "intestine: membrane columns overflow");
        cx[ncol++] = x;
        arc -= dx;
      }
    }
  }
  const PetscInt64 g0 = gid;
  const PetscInt L = c->layers;
  for (PetscInt col = 0; col < ncol; col++) {
    const double x = cx[col], sl = intestine_slope(c, x), nl = sqrt(1 + sl * sl);
    const double n[2] = {-sl / nl, 1.0 / nl};
    const double ym = intestine_profile(c, x) - off;
    const PetscBool fixed = col < c->clamp || col >= ncol - c->clamp ? PETSC_TRUE : PETSC_FALSE;
    const PetscInt k = tracking_pocket(x, c->n_pockets, c->b, 0.0);
    for (PetscInt l = 0; l < L; l++) {
      const double sh = off - l * dx; /* layer 0 on top */
      const double p[2] = {x + sh * n[0], ym + sh * n[1]};
      PetscInt idx;
      PetscCall(particles_add_owned(&s->ps, gid++, fixed ? PTYPE_WALL : PTYPE_SOLID, p, zero, m,
                                    sp->rho0, &idx));
      if (!fixed)
        s->ps.segment[idx] = PERISTALSIS_SEGMENT0 + (PetscInt)PetscMin(k, c->n_pockets - 1);
    }
  }
  PetscCall(PetscFree(cx));
  const membrane_layout mem = {.g0 = g0, .n_columns = ncol, .layers = L};
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: %" PetscInt_FMT " pockets of %g m, fluid gids 0..%" PetscInt64_FMT
      ", walls %" PetscInt64_FMT "..%" PetscInt64_FMT ", membrane %" PetscInt64_FMT
      "..%" PetscInt64_FMT " (%" PetscInt_FMT " columns x %" PetscInt_FMT " layers, %" PetscInt_FMT
      " fixed at each end), parking lot of %" PetscInt_FMT " rows at x >= %g m\n",
      c->n_pockets, c->b, c->n_fluid - 1, c->n_fluid, g0 - 1, g0, gid - 1, ncol, L, c->clamp,
      c->lot_rows, c->lot_x0));
  topology *t = s->topo;
#define G(col, l)  (g0 + (PetscInt64)(col)*L + (l))
#define FIXED(col) ((col) < c->clamp || (col) >= ncol - c->clamp)
  for (PetscInt col = 0; col < ncol; col++) {
    if (!FIXED(col))
      for (PetscInt l = 0; l + 1 < L; l++)
        PetscCall(topology_add_bond(t, G(col, l), G(col, l + 1), 0));
    if (col + 1 == ncol || (FIXED(col) && FIXED(col + 1)))
      continue;
    for (PetscInt l = 0; l < L; l++)
      PetscCall(topology_add_bond(t, G(col, l), G(col + 1, l), 0));
    for (PetscInt l = 0; l + 1 < L; l++) { /* the four corners of cell (col..col+1, l..l+1) */
      PetscCall(topology_add_angle(t, G(col + 1, l), G(col, l), G(col, l + 1), 0));
      PetscCall(topology_add_angle(t, G(col, l), G(col + 1, l), G(col + 1, l + 1), 0));
      PetscCall(topology_add_angle(t, G(col + 1, l + 1), G(col, l + 1), G(col, l), 0));
      PetscCall(topology_add_angle(t, G(col, l + 1), G(col + 1, l + 1), G(col + 1, l), 0));
    }
  }
#undef G
#undef FIXED
  PetscCheck(s->dom.lo[1] < y_bottom && c->lot_y0 + c->lot_rows * c->lot_sp < s->dom.hi[1], s->comm,
             PETSC_ERR_PLIB, "intestine: domain too small");
  const intestine_layout lay = {.n_pockets = c->n_pockets,
                                .b = c->b,
                                .dx = c->dx,
                                .level = c->level,
                                .amplitude = c->amplitude,
                                .red = c->red,
                                .n_fluid = c->n_fluid,
                                .mem = mem,
                                .peri = c->peri,
                                .body = c->body,
                                .uf_r2_min = c->uf_r2_min,
                                .uf_initial_waves = c->uf_initial_waves};
  PetscCall(intestine_tracking_register(s, &lay));
  PetscFunctionReturn(0);
}

/* Fluid past the weir is parked: a fixed particle (wall type, at rest) in its
 * own slot of the lot, > 2 h from every other particle, so that it takes no
 * part in any sum. The slot is a function of the gid: rank-count invariant. */
static PetscErrorCode intestine_park(intestine_data *c, sim *s) {
  const sph_params *sp = sph_params_get(s);
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->x[i][0] <= c->x_park)
      continue;
    const PetscInt64 g = ps->gid[i];
    PetscCheck(g >= 0 && g < c->n_fluid, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "intestine: fluid gid %" PetscInt64_FMT " out of range", g);
    const double slot[DMHS_DIM] = {c->lot_x0 + (double)(g / c->lot_rows) * c->lot_sp,
                                   c->lot_y0 + (double)(g % c->lot_rows) * c->lot_sp};
    particles_retire(ps, i, slot, sp->rho0);
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_post_step(scene *self, sim *s) {
  PetscFunctionBeginUser;
  PetscCall(intestine_park(self->data, s));
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode intestine_scene_create(scene **out) {
  intestine_data *c;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&c));
  c->n_pockets = 10;
  c->b = 0.02;
  c->dx = 2.5e-4;
  c->level = 0.0046;
  c->amplitude = 0.003;
  c->layers = 3;
  c->wall_height = 0.03;
  c->red_pocket = 4;
  /* a line over 10 waves with each wave's pulse fits to R^2 > 0.997; a slope that
   * changes by 1.5x halfway, or a front that stalls, falls below 0.99
   * (doc/theory.md, "Peristalsis and tracking") */
  c->uf_r2_min = 0.99;
  /* the thesis's front slows after ~40 s at T_w = 13.8 s: three waves */
  c->uf_initial_waves = 3;
  (*out)->name = "intestine";
  (*out)->set_from_options = intestine_set_from_options;
  (*out)->build = intestine_build;
  (*out)->post_step = intestine_post_step;
  (*out)->destroy = intestine_destroy;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
