/* struct sim: the run-control options pass, setup (scene, modules, ghosts,
 * pre-flight checks), the step loop and teardown.
 *
 * One step:
 *   time-step limits (check or adapt dt) -> first kick + drift -> migrate (wrap / owners) -> ghosts
 * + pair list
 *   -> modules' compute (forces, density rates) -> second kick
 *   -> state check (stop before any NaN is written) -> scene diagnostics -> progress */
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"
#include "dmhs/registry.h"
#include "dmhs/integrate.h"
#include "dmhs/migrate.h"
#include "dmhs/progress.h"
#include "dmhs/dump.h" /* mpi */
#include "dmhs/substep.h"

const char *const preflight_action_names[] = {"error", "warn", "preflight_action", "PREFLIGHT_",
                                              NULL};

static PetscErrorCode sim_set_from_options(sim *s, char *scene_name, size_t len) {
  char names[256];
  PetscBool traceback = PETSC_FALSE; /* acted on by main, before any option is read here */
  PetscFunctionBeginUser;
  PetscCall(registry_scene_names(names, sizeof(names)));
  PetscOptionsBegin(s->comm, NULL, "dmhs run control", NULL);
  PetscCall(PetscOptionsString("-scene", names, NULL, scene_name, scene_name, len, NULL));
  PetscCall(PetscOptionsReal("-t_end", "End time [s]", NULL, s->t_end, &s->t_end, NULL));
  PetscCall(PetscOptionsEnum(
      "-preflight", "When dt exceeds a stability limit: error (stop) or warn", NULL,
      preflight_action_names, (PetscEnum)s->preflight, (PetscEnum *)&s->preflight, NULL));
  PetscCall(PetscOptionsString("-output_dir", "Directory for every output file", NULL,
                               s->output_dir, s->output_dir, sizeof(s->output_dir), NULL));
  PetscCall(PetscOptionsReal("-output_interval",
                             "Physical time between output rows/snapshots [s] (0 = t_end/100)",
                             NULL, s->output_interval, &s->output_interval, NULL));
  PetscCall(PetscOptionsReal("-progress_interval",
                             "Physical time between progress lines [s] (0 = t_end/20)", NULL,
                             s->progress_interval, &s->progress_interval, NULL));
  PetscCall(
      PetscOptionsBool("-quiet", "Silence the progress lines", NULL, s->quiet, &s->quiet, NULL));
  PetscCall(PetscOptionsReal(
      "-neighbour_skin",
      "Verlet skin as a fraction of the longest interaction reach [1] (0 = rebuild ghosts "
      "and pairs every step)",
      NULL, s->skin_ratio, &s->skin_ratio, NULL));
  PetscCall(PetscOptionsBool("-dmhs_traceback",
                             "On an error, PETSc's full traceback instead of the one-line message",
                             NULL, traceback, &traceback, NULL));
  PetscOptionsEnd();
  PetscCall(timestep_set_from_options(s));
  PetscCheck(s->t_end > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-t_end must be > 0 (got %g)",
             s->t_end);
  PetscCheck(s->skin_ratio >= 0 && s->skin_ratio <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-neighbour_skin must be in [0, 1] (got %g)", s->skin_ratio);
  PetscCheck(s->output_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-output_interval must be >= 0 (got %g)", s->output_interval);
  PetscCheck(s->progress_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-progress_interval must be >= 0 (got %g)", s->progress_interval);
  if (s->output_interval == 0)
    s->output_interval = s->t_end / 100;
  if (s->progress_interval == 0)
    s->progress_interval = s->t_end / 20;
  PetscFunctionReturn(0);
}

/* An option nobody read is a typo or belongs to a module this scene does not
 * enable: either way the user's intent would be silently ignored. */
static PetscErrorCode sim_check_unused_options(sim *s) {
  PetscInt n;
  char **names, **values;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt k = 0; k < n; k++)
    PetscCall(PetscPrintf(s->comm,
                          "dmhs: option -%s %s was not used by scene '%s' or its modules\n",
                          names[k], values[k] ? values[k] : "", s->scn->name));
  const PetscInt n_unused = n;
  const PetscBool clean = n == 0 ? PETSC_TRUE : PETSC_FALSE;
  const char *first = n ? names[0] : "";
  char first_copy[256];
  PetscCall(PetscStrncpy(first_copy, first, sizeof(first_copy)));
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(clean, s->comm, PETSC_ERR_ARG_WRONG,
             "unknown or unused option -%s (and %" PetscInt_FMT
             " more); run with -help to list the options",
             first_copy, n_unused - 1);
  PetscFunctionReturn(0);
}

static PetscErrorCode sim_prepare_output_dir(sim *s) {
  char probe[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  if (s->rank == 0) {
    char partial[PETSC_MAX_PATH_LEN];
    PetscCall(PetscStrncpy(partial, s->output_dir, sizeof(partial)));
    /* mkdir -p: each prefix in turn */
    for (char *c = partial + 1;; c++) {
      const char saved = *c;
      if (saved != '/' && saved != 0)
        continue;
      *c = 0;
      PetscCheck(mkdir(partial, 0777) == 0 || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
                 "-output_dir %s: cannot create %s: %s", s->output_dir, partial, strerror(errno));
      *c = saved;
      if (!saved)
        break;
    }
    PetscCall(PetscSNPrintf(probe, sizeof(probe), "%s/.dmhs-write-test", s->output_dir));
    FILE *f = fopen(probe, "w");
    PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output_dir %s: not writable (%s)",
               s->output_dir, strerror(errno));
    fclose(f);
    unlink(probe);
  }
  PetscCallMPI(MPI_Barrier(s->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_output_path(const sim *s, const char *name, char *path, size_t len) {
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, len, "%s/%s", s->output_dir, name));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_enable_module(sim *s, const char *name, module **out) {
  PetscFunctionBeginUser;
  PetscCheck(s->n_modules < SIM_MAX_MODULES, s->comm, PETSC_ERR_PLIB, "too many modules");
  for (int m = 0; m < s->n_modules; m++)
    PetscCheck(strcmp(s->modules[m]->name, name), s->comm, PETSC_ERR_PLIB,
               "module %s enabled twice", name);
  PetscCall(registry_create_module(name, &s->modules[s->n_modules]));
  if (out)
    *out = s->modules[s->n_modules];
  s->n_modules++;
  PetscFunctionReturn(0);
}

module *sim_find_module(const sim *s, const char *name) {
  for (int m = 0; m < s->n_modules; m++)
    if (!strcmp(s->modules[m]->name, name))
      return s->modules[m];
  return NULL;
}

PetscErrorCode sim_rebuild_neighbours(sim *s) {
  double lo[DMHS_DIM], hi[DMHS_DIM];
  PetscFunctionBeginUser;
  for (int k = 0; k < DMHS_DIM; k++) {
    lo[k] = s->dom.lo[k] - s->hal.width;
    hi[k] = s->dom.hi[k] + s->hal.width;
  }
  const double cutoff = PetscMax(s->pair_cutoff, s->list_cutoff);
  if (s->pair_cutoff > 0) /* owned rows in the order the pair build will visit them */
    PetscCall(cells_sort_owned_rows(&s->ps, lo, hi, cutoff));
  PetscCall(halo_build(&s->hal, &s->dom, &s->part, &s->ps)); /* mpi: + partition */
  /* solids: bonds/angles by gid -> local rows, and the bonded pairs the pair list leaves
   * out */
  if (s->topo) {
    PetscCall(PetscLogEventBegin(events.topology, 0, 0, 0, 0));
    PetscCall(topology_resolve(s->topo, &s->ps));
    PetscCall(PetscLogEventEnd(events.topology, 0, 0, 0, 0));
    s->cel.excl = s->topo->special_include ? NULL : s->topo;
  }
  if (s->pair_cutoff > 0) {
    PetscCall(PetscLogEventBegin(events.pairs, 0, 0, 0, 0));
    PetscCall(cells_build_pairs(&s->cel, &s->ps, lo, hi, cutoff));
    PetscCall(PetscLogEventEnd(events.pairs, 0, 0, 0, 0));
    if (s->debug_halo)
      PetscCall(halo_check_pairs(s)); /* mpi */
  }
  PetscFunctionReturn(0);
}

/* Names of every FIELD_GHOST field: what a full ghost refresh copies (diagnostics, restart). */
static const char *const *sim_ghost_fields(int *n) {
  static const char *names[32];
  static int count = -1;
  if (count < 0) {
    size_t nf;
    const field_desc *t = fields_table(&nf);
    count = 0;
    for (size_t k = 0; k < nf && count < 32; k++)
      if (t[k].flags & FIELD_GHOST)
        names[count++] = t[k].name;
  }
  *n = count;
  return names;
}

/* Verlet lists: rebuild when a particle may have moved half the skin since the
 * last build (then a pair can have come from outside the list radius into the
 * interaction range), or when the partition is due for its balance check. The
 * order of every particle's sums follows the cells of the last build, so the
 * build steps must not depend on the rank count. */
static PetscErrorCode sim_needs_rebuild(sim *s, PetscBool *rebuild) {
  const particles *ps = &s->ps;
  double local = 0, global;
  PetscFunctionBeginUser;
  *rebuild = PETSC_TRUE;
  if (s->skin <= 0)
    PetscFunctionReturn(0);
  /* on every rank count alike, so that runs stay bitwise rank-count invariant */
  if (s->part.interval > 0 && s->step % s->part.interval == 0)
    PetscFunctionReturn(0);
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const double dx = ps->x[i][0] - ps->x_build[i][0], dy = ps->x[i][1] - ps->x_build[i][1];
    local = PetscMax(local, dx * dx + dy * dy);
  }
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *rebuild = global > 0.25 * s->skin * s->skin ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The fields a step refreshes on ghosts between builds: those some module reads there
 * (module.ghost_reads) and that can change between builds (not FIELD_FIXED). */
static PetscErrorCode sim_collect_ghost_reads(sim *s) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  PetscFunctionBeginUser;
  s->n_ghost_step_fields = 0;
  for (int m = 0; m < s->n_modules; m++)
    for (const char *const *r = s->modules[m]->ghost_reads; r && *r; r++) {
      const field_desc *f = fields_find(*r);
      PetscCheck(f && (f->flags & FIELD_GHOST), s->comm, PETSC_ERR_PLIB,
                 "module %s reads field '%s' on ghosts, which is not a ghost field of this run",
                 s->modules[m]->name, *r);
    }
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_GHOST) || (t[k].flags & FIELD_FIXED))
      continue;
    PetscBool read = PETSC_FALSE;
    for (int m = 0; m < s->n_modules && !read; m++)
      for (const char *const *r = s->modules[m]->ghost_reads; r && *r && !read; r++)
        read = strcmp(*r, t[k].name) ? PETSC_FALSE : PETSC_TRUE;
    if (!read)
      continue;
    PetscCheck(s->n_ghost_step_fields <
                   (int)(sizeof(s->ghost_step_fields) / sizeof(s->ghost_step_fields[0])),
               s->comm, PETSC_ERR_PLIB, "too many ghost fields");
    s->ghost_step_fields[s->n_ghost_step_fields++] = t[k].name;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode sim_update_neighbours(sim *s, PetscBool force) {
  PetscBool rebuild = force;
  PetscFunctionBeginUser;
  if (!rebuild)
    PetscCall(sim_needs_rebuild(s, &rebuild));
  if (rebuild) {
    PetscCall(migrate_particles(s));
    PetscCall(sim_rebuild_neighbours(s));
    PetscCall(PetscArraycpy(s->ps.x_build, s->ps.x, s->ps.n_owned));
    s->n_rebuilds++;
  } else if (s->n_ghost_step_fields > 0)
    PetscCall(halo_forward(&s->hal, &s->ps, s->ghost_step_fields, s->n_ghost_step_fields));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_refresh_ghosts(sim *s) {
  int n;
  const char *const *names = sim_ghost_fields(&n);
  PetscFunctionBeginUser;
  PetscCall(halo_forward(&s->hal, &s->ps, names, n));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_rebuild_as_last_built(sim *s) {
  particles *ps = &s->ps;
  int n;
  const char *const *names = sim_ghost_fields(&n);
  PetscFunctionBeginUser;
  /* build with x_build in the x slot; both migrate together, so rows stay paired */
  double(*current)[DMHS_DIM] = ps->x;
  ps->x = ps->x_build;
  ps->x_build = current;
  PetscCall(migrate_particles(s));
  PetscCall(sim_rebuild_neighbours(s));
  current = ps->x_build;
  ps->x_build = ps->x;
  ps->x = current;
  PetscCall(halo_forward(&s->hal, ps, names, n));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_add_module_forces(sim *s, module_filter keep) {
  PetscFunctionBeginUser;
  /* phase one: what the computes read from one another, at this evaluation's time */
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->prepare && (!keep || keep(s->modules[m])))
      PetscCall(s->modules[m]->prepare(s->modules[m], s));
  for (int m = 0; m < s->n_modules; m++)
    if (!keep || keep(s->modules[m]))
      PetscCall(s->modules[m]->compute(s->modules[m], s));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_compute_module_forces(sim *s, module_filter keep) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(ps->a, n));
  PetscCall(PetscArrayzero(ps->drho, n));
  PetscCall(sim_add_module_forces(s, keep));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_compute_forces(sim *s) {
  PetscFunctionBeginUser;
  if (s->ts.subcycling) {
    PetscCall(substep_compute_forces(s)); /* the solids' own share kept apart */
    PetscFunctionReturn(0);
  }
  PetscCall(sim_compute_module_forces(s, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode sim_view(sim *s) {
  PetscViewer v = PETSC_VIEWER_STDOUT_(s->comm);
  PetscInt n_local[PTYPE_COUNT], n[PTYPE_COUNT];
  PetscFunctionBeginUser;
  for (int t = 0; t < PTYPE_COUNT; t++)
    n_local[t] = particles_count_type(&s->ps, (particle_type)t);
  PetscCallMPI(MPI_Allreduce(n_local, n, PTYPE_COUNT, MPIU_INT, MPI_SUM, s->comm));
  PetscCall(PetscViewerASCIIPrintf(v, "dmhs %s: scene %s on %d rank(s)\n", DMHS_VERSION,
                                   s->scn->name, (int)s->size));
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "particles: %" PetscInt_FMT " fluid, %" PetscInt_FMT
                                   " wall, %" PetscInt_FMT " solid; rest spacing dx = %g m\n",
                                   n[PTYPE_FLUID], n[PTYPE_WALL], n[PTYPE_SOLID], s->dx));
  PetscCall(PetscViewerASCIIPrintf(
      v, "box: [%g, %g] x [%g, %g] m, periodic x: %s, y: %s; ghost width %g m\n", s->dom.lo[0],
      s->dom.hi[0], s->dom.lo[1], s->dom.hi[1], s->dom.periodic[0] ? "yes" : "no",
      s->dom.periodic[1] ? "yes" : "no", s->hal.width));
  PetscCall(PetscViewerASCIIPrintf(v, "run: t_end = %g s, output every %g s to %s/\n", s->t_end,
                                   s->output_interval, s->output_dir));
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->view)
      PetscCall(s->modules[m]->view(s->modules[m], s, v));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_create(MPI_Comm comm, sim **out, PetscBool *help_only) {
  sim *s;
  char scene_name[64] = "poiseuille";
  PetscBool help;
  PetscFunctionBeginUser;
  PetscCall(events_register());
  PetscCall(registry_initialize());
  PetscCall(PetscNew(&s));
  *out = s;
  s->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &s->rank));
  PetscCallMPI(MPI_Comm_size(comm, &s->size));
  s->t_end = 1.0;
  s->skin_ratio = 0.1;
  s->preflight = PREFLIGHT_ERROR;
  PetscCall(PetscStrncpy(s->output_dir, "output", sizeof(s->output_dir)));
  PetscCall(particles_create(&s->ps));
  PetscCall(cells_create(&s->cel));

  PetscCall(PetscLogStagePush(events.stage_setup));
  /* -help: main takes it off the command line; one in an options file is taken off here */
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  *help_only = help = help || *help_only;
  PetscCall(PetscOptionsClearValue(NULL, "-help"));
  PetscCall(sim_set_from_options(s, scene_name, sizeof(scene_name)));
  /* mpi: decomposition, migration check, halo check and final dump */
  PetscCall(partition_set_from_options(&s->part, s));
  PetscCall(migrate_set_from_options(&s->mig, s));
  PetscCall(halo_check_set_from_options(s));
  PetscCall(dump_set_from_options(s));
  PetscCall(io_set_from_options(s)); /* io: snapshots, checkpoints, -restart */
  if (help) {
    PetscCall(registry_print_help(s, scene_name));
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }

  /* scene options (they set module defaults and enable modules), then modules' own */
  PetscCall(registry_create_scene(scene_name, &s->scn));
  PetscCall(s->scn->set_from_options(s->scn, s));
  for (int m = 0; m < s->n_modules; m++)
    PetscCall(s->modules[m]->set_from_options(s->modules[m], s));
  PetscCall(sim_check_unused_options(s));

  PetscCall(sim_prepare_output_dir(s));
  PetscCall(io_setup(s)); /* io: run.json, signal handlers */
  PetscCall(s->scn->build(s->scn, s));
  double reach = 0;
  for (int m = 0; m < s->n_modules; m++) {
    reach = PetscMax(reach, s->modules[m]->reach);
    if (s->modules[m]->needs & MODULE_NEEDS_PAIRS)
      s->pair_cutoff = PetscMax(s->pair_cutoff, s->modules[m]->reach);
  }
  s->skin = s->skin_ratio * reach;
  s->list_cutoff = s->pair_cutoff > 0 ? s->pair_cutoff + s->skin : 0;
  PetscCall(domain_check_ghost_width(&s->dom, reach + s->skin));
  PetscCall(halo_create(&s->hal, reach + s->skin, s->comm));
  PetscCall(partition_setup(&s->part, s)); /* mpi: each rank keeps its share of the scene */
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->setup)
      PetscCall(s->modules[m]->setup(s->modules[m], s));
  /* no pair list when every module that wants neighbours walks the cells itself */
  s->cel.no_pair_list = s->debug_halo ? PETSC_FALSE : PETSC_TRUE;
  for (int m = 0; m < s->n_modules; m++)
    if ((s->modules[m]->needs & MODULE_NEEDS_PAIRS) && !(s->modules[m]->needs & MODULE_CELLS_ONLY))
      s->cel.no_pair_list = PETSC_FALSE;
  PetscCall(sim_collect_ghost_reads(s));

  PetscCall(sim_view(s));
  PetscCall(integrate_stability_report(s));
  s->next_output_t = s->output_interval;
  s->next_progress_t = s->progress_interval;

  /* forces at t = 0 for the first kick */
  PetscCall(sim_update_neighbours(s, PETSC_TRUE));
  PetscCall(sim_compute_forces(s));
  PetscCall(integrate_check_state(s));
  PetscCall(io_restart(s)); /* io: with -restart, the checkpoint's state replaces the built one */
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode sim_run(sim *s) {
  PetscInt n_owned_global, n_local = s->ps.n_owned;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&n_local, &n_owned_global, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscCall(PetscLogStagePush(events.stage_steps));
  /* io: a restarted run already diagnosed and wrote out this state */
  if (!s->io.restarted) {
    PetscCall(PetscLogEventBegin(events.diagnostics, 0, 0, 0, 0));
    if (s->scn->diagnose)
      PetscCall(s->scn->diagnose(s->scn, s));
    PetscCall(PetscLogEventEnd(events.diagnostics, 0, 0, 0, 0));
    PetscCall(io_output(s));
  }
  s->loop_start_wtime = MPI_Wtime();
  /* stop at the step nearest t_end */
  while (s->t < s->t_end - 0.5 * s->dt) {
    PetscCall(timestep_before_step(s)); /* the limits the state now sets: check or adapt dt */
    PetscCall(integrate_first_half(s));
    if (s->ts.subcycling)
      PetscCall(substep_solids(s)); /* the solids' sub-steps */
    timestep_advance(s);
    PetscCall(sim_update_neighbours(s, s->force_rebuild));
    s->force_rebuild = PETSC_FALSE;
    PetscCall(sim_compute_forces(s));
    PetscCall(integrate_second_half(s));
    PetscCall(integrate_check_state(s));
    for (int m = 0; m < s->n_modules; m++)
      if (s->modules[m]->post_step)
        PetscCall(s->modules[m]->post_step(s->modules[m], s));
    s->particle_steps += n_owned_global;
    PetscCall(PetscLogEventBegin(events.diagnostics, 0, 0, 0, 0));
    if (s->scn->diagnose)
      PetscCall(s->scn->diagnose(s->scn, s));
    PetscCall(PetscLogEventEnd(events.diagnostics, 0, 0, 0, 0));
    if (s->t >= s->next_output_t - 0.5 * s->dt) {
      PetscCall(io_output(s)); /* io: snapshot + XDMF */
      s->next_output_t += s->output_interval;
    }
    if (s->t >= s->next_progress_t - 0.5 * s->dt) {
      if (!s->quiet)
        PetscCall(progress_print(s));
      s->next_progress_t += s->progress_interval;
    }
    PetscBool stop; /* io: checkpoint at the interval; on SIGTERM/SIGUSR1 also stop */
    PetscCall(io_after_step(s, &stop));
    if (stop)
      break;
  }
  s->loop_seconds = MPI_Wtime() - s->loop_start_wtime;
  PetscCall(PetscLogStagePop());
  if (s->scn->finish)
    PetscCall(s->scn->finish(s->scn, s));
  PetscCall(progress_summary(s));
  PetscCall(dump_final(s));              /* mpi */
  PetscCall(migrate_report(&s->mig, s)); /* mpi */
  PetscCall(timestep_finish(s));
  PetscCall(io_finish(s)); /* io: final checkpoint, run.json */
  PetscFunctionReturn(0);
}

PetscErrorCode sim_destroy(sim **sp) {
  sim *s = *sp;
  PetscFunctionBeginUser;
  if (!s)
    PetscFunctionReturn(0);
  for (int m = 0; m < s->n_modules; m++) {
    if (s->modules[m]->destroy)
      PetscCall(s->modules[m]->destroy(s->modules[m]));
    PetscCall(PetscFree(s->modules[m]));
  }
  if (s->scn) {
    if (s->scn->destroy)
      PetscCall(s->scn->destroy(s->scn));
    PetscCall(PetscFree(s->scn));
  }
  PetscCall(io_destroy(s));
  PetscCall(topology_destroy(&s->topo)); /* solids */
  PetscCall(halo_destroy(&s->hal));
  PetscCall(partition_destroy(&s->part)); /* mpi */
  PetscCall(cells_destroy(&s->cel));
  PetscCall(particles_destroy(&s->ps));
  PetscCall(registry_finalize());
  options_forget();
  PetscCall(PetscFree(*sp));
  PetscFunctionReturn(0);
}
