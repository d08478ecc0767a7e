/* The driver: the run-control options pass, setup (scene, modules, ghosts,
 * pre-flight checks), the step loop and teardown.
 *
 * One step:
 *   time-step limits (check or adapt dt) -> first kick + drift -> migrate (wrap / owners) -> ghosts
 * + pair list
 *   -> modules' compute (forces, density rates) -> second kick
 *   -> state check (stop before any NaN is written) -> modules' and scene's post_step
 *   -> the due diagnostics (each on its own schedule, diagnostic.h) -> output
 *   -> one reduction: a stop signal on any rank, rank 0's clock -> progress (progress.h)
 *   -> checkpoint at the interval, or on a stop signal (and stop)
 * After the loop, a final output when the last step was not an output time. */
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>
#include "dmhs/run.h"
#include "dmhs/diagnostics.h"
#include "dmhs/io.h"
#include "dmhs/timestep.h"
#include "dmhs/run_control.h"
#include "dmhs/sim.h"
#include "dmhs/neighbours.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"
#include "dmhs/registry.h"
#include "dmhs/modules.h"
#include "dmhs/integrate.h"
#include "dmhs/migrate.h"
#include "dmhs/progress.h"
#include "dmhs/dump.h" /* mpi */
#include "dmhs/substep.h"
#include "dmhs/stop_signal.h"
#include "dmhs/outdir.h"
#include "dmhs/console_log.h"
#include "dmhs/build_info.h"

const char *const preflight_action_names[] = {"error", "warn", "preflight_action", "PREFLIGHT_",
                                              NULL};

static PetscErrorCode run_set_from_options(sim *s, run_control *rc, char *scene_name, size_t len) {
  char names[256];
  PetscBool traceback = PETSC_FALSE; /* acted on by main, before any option is read here */
  PetscFunctionBeginUser;
  PetscCall(registry_scene_names(names, sizeof(names)));
  PetscOptionsBegin(s->comm, NULL, "dmhs run control", NULL);
  PetscCall(options_read_string("-scene", names, NULL, scene_name, scene_name, len, NULL));
  PetscCall(
      options_read_real("-t_end", "End time [s]", NULL, s->t_end, &s->t_end, &s->t_end_given));
  PetscCall(options_run_control("-t_end"));
  PetscCall(options_read_enum("-preflight",
                              "When dt exceeds a stability limit: error (stop) or warn", NULL,
                              preflight_action_names, (PetscEnum)rc->ts.on_exceeded,
                              (PetscEnum *)&rc->ts.on_exceeded, NULL));
  PetscCall(options_run_control("-preflight"));
  PetscCall(options_read_string("-output_dir", "Directory for every output file", NULL,
                                rc->output_dir, rc->output_dir, sizeof(rc->output_dir), NULL));
  PetscCall(options_run_control("-output_dir"));
  PetscCall(options_read_real("-output_interval",
                              "Physical time between output rows/snapshots [s] (0 = t_end/100)",
                              NULL, rc->output_interval, &rc->output_interval, NULL));
  PetscCall(options_run_control("-output_interval"));
  PetscCall(options_read_real(
      "-neighbour_skin",
      "Verlet skin as a fraction of the longest interaction reach [1] (0 = rebuild ghosts "
      "and pairs every step)",
      NULL, s->skin_ratio, &s->skin_ratio, NULL));
  PetscCall(options_read_bool("-dmhs_traceback",
                              "On an error, PETSc's full traceback instead of the one-line message",
                              NULL, traceback, &traceback, NULL));
  PetscCall(options_run_control("-dmhs_traceback"));
  PetscOptionsEnd();
  PetscCall(timestep_set_from_options(s, &rc->ts));
  PetscCheck(s->t_end > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-t_end must be > 0 (got %g)",
             s->t_end);
  PetscCheck(s->skin_ratio >= 0 && s->skin_ratio <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-neighbour_skin must be in [0, 1] (got %g)", s->skin_ratio);
  PetscCheck(rc->output_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-output_interval must be >= 0 (got %g)", rc->output_interval);
  PetscCall(progress_set_from_options(s, rc));
  s->part.quiet = rc->quiet;
  /* run.json: how often a live run's heartbeat comes at the latest */
  s->io->heartbeat_interval = rc->progress.wall_interval;
  PetscFunctionReturn(0);
}

/* An option nobody read is a typo or belongs to a module this scene does not
 * enable: either way the user's intent would be silently ignored. */
static PetscErrorCode sim_check_unused_options(sim *s) {
  PetscInt n;
  char **names, **values;
  PetscFunctionBeginUser;
  char first[256] = "", first_hint[600] = "", more[64] = "";
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt k = 0; k < n; k++) {
    char name[256], near[512], hint[600] = "";
    PetscCall(PetscSNPrintf(name, sizeof(name), "-%s", names[k]));
    PetscCall(options_nearest(name, near, sizeof(near))); /* the options this run read */
    if (near[0])
      PetscCall(PetscSNPrintf(hint, sizeof(hint), " (did you mean %s?)", near));
    PetscCall(PetscPrintf(s->comm,
                          "dmhs: option %s %s was not used by scene '%s' or its modules%s\n", name,
                          values[k] ? values[k] : "", s->scene_name, hint));
    if (k == 0) {
      PetscCall(PetscStrncpy(first, name, sizeof(first)));
      PetscCall(PetscStrncpy(first_hint, hint, sizeof(first_hint)));
    }
  }
  const PetscInt n_unused = n;
  if (n_unused > 1)
    PetscCall(PetscSNPrintf(more, sizeof(more), " and %" PetscInt_FMT " more", n_unused - 1));
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(n_unused == 0, s->comm, PETSC_ERR_ARG_WRONG,
             "unknown or unused option %s%s%s; run with -help to list the options", first,
             first_hint, more);
  PetscFunctionReturn(0);
}

static PetscErrorCode run_prepare_output_dir(sim *s, const char *dir) {
  char probe[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  if (s->rank == 0) {
    char partial[PETSC_MAX_PATH_LEN];
    PetscCall(PetscStrncpy(partial, dir, sizeof(partial)));
    /* mkdir -p: each prefix in turn */
    for (char *c = partial + 1;; c++) {
      const char saved = *c;
      if (saved != '/' && saved != 0)
        continue;
      *c = 0;
      PetscCheck(mkdir(partial, 0777) == 0 || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
                 "-output_dir %s: cannot create %s: %s", dir, partial, strerror(errno));
      *c = saved;
      if (!saved)
        break;
    }
    PetscCall(PetscSNPrintf(probe, sizeof(probe), "%s/.dmhs-write-test", dir));
    FILE *f = fopen(probe, "w");
    PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output_dir %s: not writable (%s)", dir,
               strerror(errno));
    fclose(f);
    unlink(probe);
  }
  PetscCallMPI(MPI_Barrier(s->comm));
  PetscFunctionReturn(0);
}

/* Rank 0 clears what an earlier run left in dir (outdir.h): interrupted writes' .tmp files,
 * and, unless this run continues from a checkpoint, that run's snapshots and index. */
static PetscErrorCode run_clear_output_dir(const sim *s, const char *dir, PetscBool restarting) {
  PetscFunctionBeginUser;
  if (s->rank == 0) {
    const int n_tmp = outdir_remove_tmp(dir);
    const int n_snap = restarting ? 0 : outdir_remove_snapshots(dir, 0);
    if (n_tmp || n_snap)
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "output directory %s: removed %d unfinished .tmp file(s) and %d "
                            "snapshot/index file(s) of an earlier run\n",
                            dir, n_tmp, n_snap));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode sim_compute_forces(sim *s) {
  PetscFunctionBeginUser;
  if (s->substeps.on) {
    PetscCall(substep_compute_forces(s)); /* the solids' own share kept apart */
    PetscFunctionReturn(0);
  }
  PetscCall(sim_compute_module_forces(s, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode run_view(sim *s, const run_control *rc) {
  PetscViewer v = PETSC_VIEWER_STDOUT_(s->comm);
  PetscInt n_local[PTYPE_COUNT], n[PTYPE_COUNT];
  PetscFunctionBeginUser;
  for (int t = 0; t < PTYPE_COUNT; t++)
    n_local[t] = particles_count_type(&s->ps, (particle_type)t);
  PetscCallMPI(MPI_Allreduce(n_local, n, PTYPE_COUNT, MPIU_INT, MPI_SUM, s->comm));
  PetscCall(PetscViewerASCIIPrintf(v, "dmhs %s (commit %s): scene %s on %d rank(s)\n", DMHS_VERSION,
                                   dmhs_commit, s->scene_name, (int)s->size));
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "particles: %" PetscInt_FMT " fluid, %" PetscInt_FMT
                                   " wall, %" PetscInt_FMT " solid; rest spacing dx = %g m\n",
                                   n[PTYPE_FLUID], n[PTYPE_WALL], n[PTYPE_SOLID], s->dx));
  PetscCall(PetscViewerASCIIPrintf(
      v, "box: [%g, %g] x [%g, %g] m, periodic x: %s, y: %s; ghost width %g m\n", s->dom.lo[0],
      s->dom.hi[0], s->dom.lo[1], s->dom.hi[1], s->dom.periodic[0] ? "yes" : "no",
      s->dom.periodic[1] ? "yes" : "no", s->hal.width));
  PetscCall(PetscViewerASCIIPrintf(v, "run: t_end = %g s, output every %g s to %s/\n", s->t_end,
                                   rc->output_interval, rc->output_dir));
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->view)
      PetscCall(s->modules[m]->view(s->modules[m], s, v));
  if (s->n_diagnostics) {
    PetscCall(PetscViewerASCIIPrintf(v, "diagnostics:"));
    for (int k = 0; k < s->n_diagnostics; k++) {
      const diagnostic *d = s->diagnostics[k];
      PetscCall(PetscViewerASCIIPrintf(v, "%s %s%s%s%s", k ? "," : "", d->name,
                                       d->output ? " (" : "", d->output ? d->output : "",
                                       d->output ? ")" : ""));
    }
    PetscCall(PetscViewerASCIIPrintf(v, "\n"));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode run_create(MPI_Comm comm, dmhs_run **out, PetscBool *help_only) {
  dmhs_run *r;
  sim *s;
  char scene_name[64] = "poiseuille";
  PetscBool help;
  PetscFunctionBeginUser;
  PetscCall(events_register());
  PetscCall(registry_initialize());
  PetscCall(PetscNew(&r));
  *out = r;
  PetscCall(PetscNew(&r->core));
  s = r->core;
  run_control *rc = &r->control;
  /* io's own state, which the core state only points to */
  PetscCall(PetscNew(&s->io));
  s->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &s->rank));
  PetscCallMPI(MPI_Comm_size(comm, &s->size));
  /* io: from now on a stop signal waits for the first safe point (step 0) */
  PetscCall(stop_signal_install(s->rank));
  rc->last_output_step = -1;
  s->t_end = 1.0;
  s->skin_ratio = 0.1;
  rc->ts.on_exceeded = PREFLIGHT_ERROR;
  PetscCall(PetscStrncpy(rc->output_dir, "output", sizeof(rc->output_dir)));
  PetscCall(particles_create(&s->ps));
  PetscCall(cells_create(&s->cel));

  PetscCall(PetscLogStagePush(events.stage_setup));
  /* -help: main takes it off the command line; one in an options file is taken off here */
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  *help_only = help = help || *help_only;
  PetscCall(PetscOptionsClearValue(NULL, "-help"));
  PetscCall(run_set_from_options(s, rc, scene_name, sizeof(scene_name)));
  /* mpi: decomposition, migration check, halo check and final dump */
  PetscCall(partition_set_from_options(&s->part, s));
  PetscCall(migrate_set_from_options(&s->mig, s));
  PetscCall(halo_check_set_from_options(s));
  PetscCall(dump_set_from_options(s));
  PetscCall(io_set_from_options(s)); /* io: snapshots, checkpoints, -restart */
  PetscCall(io_set_output_dir(s, rc->output_dir));
  /* the schedule's next times: a restart continues it */
  PetscCall(io_checkpoint_keep_real(s, "next_output_t", &rc->next_output_t));
  PetscCall(io_checkpoint_keep_real(s, "next_progress_t", &rc->next_progress_t));
  if (help) {
    PetscCall(registry_print_help(s, scene_name));
    PetscCall(PetscLogStagePop());
    PetscFunctionReturn(0);
  }

  /* scene options (they set module defaults and enable modules), then modules' own */
  PetscCall(registry_create_scene(scene_name, &r->scn));
  scene *scn = r->scn;
  s->scene_name = scn->name;
  PetscCall(scn->set_from_options(scn, s));
  /* the intervals that follow t_end, once the scene has set its default (sim_default_t_end) */
  if (rc->output_interval == 0)
    rc->output_interval = s->t_end / 100;
  if (rc->progress_interval == 0)
    rc->progress_interval = s->t_end / 20;
  for (int m = 0; m < s->n_modules; m++) {
    const module *mod = s->modules[m];
    PetscCall(mod->set_from_options(s->modules[m], s));
    /* a module that moves more than the solids on the sub-steps (by its option -<name>_substeps)
     * means nothing without them */
    PetscCheck(!mod->substep_members || !mod->solid_internal || s->substeps.on, s->comm,
               PETSC_ERR_ARG_INCOMP,
               "-%s_substeps runs the %s on the solid sub-steps, but there are none "
               "(-solid_substeps 1): give -solid_substeps 0 (automatic) or N > 1",
               mod->name, mod->name);
  }
  PetscCall(sim_check_unused_options(s));

  PetscCall(run_prepare_output_dir(s, rc->output_dir));
  /* from here rank 0's console goes to <output_dir>/dmhs.log too, what it printed so far first */
  PetscCall(console_log_open(rc->output_dir, s->io->restart_file));
  PetscCall(
      run_clear_output_dir(s, rc->output_dir, s->io->restart_file[0] ? PETSC_TRUE : PETSC_FALSE));
  PetscCall(io_setup(s)); /* io: run.json, signal handlers */
  PetscCall(scn->build(scn, s));
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
  PetscCall(neighbours_collect_ghost_reads(s));

  PetscCall(run_view(s, rc));
  rc->next_output_t = rc->output_interval;
  rc->next_progress_t = rc->progress_interval;

  /* the first neighbour build, then the limits at t = 0 (with the bonds' and angles' local
   * lists in place: asking a module's max_dt changes nothing), then the forces at t = 0 for
   * the first kick (the limits see no acceleration yet, as a restart's checkpoint does not) */
  PetscCall(neighbours_update(s, PETSC_TRUE));
  PetscCall(timestep_stability_report(s, &rc->ts));
  PetscCall(sim_compute_forces(s));
  PetscCall(integrate_check_state(s));
  /* with -restart, the checkpoint's state replaces the built one: ghosts and pairs as the
   * checkpointed run last built them, the state checked, then io's files follow */
  PetscCall(io_restart_read(s));
  if (s->io->restarted) {
    PetscCall(neighbours_rebuild_as_last_built(s));
    PetscCall(integrate_check_state(s));
  }
  PetscCall(io_restart_continue(s));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

/* The state the run ends with, when its last step was not an output time (a shortened
 * -t_end, a stop signal): the end checkpoint first, so that a run continued from it never
 * sees what follows, then the at-output diagnostics' rows and a snapshot in the XDMF. */
static PetscErrorCode run_final_output(sim *s, run_control *rc) {
  PetscFunctionBeginUser;
  if (rc->last_output_step == s->step)
    PetscFunctionReturn(0);
  PetscCall(io_checkpoint_at_end(s));
  s->output_step = PETSC_TRUE;
  PetscCall(PetscLogEventBegin(events.diagnostics, 0, 0, 0, 0));
  PetscCall(diagnostics_sample_final(s));
  PetscCall(PetscLogEventEnd(events.diagnostics, 0, 0, 0, 0));
  PetscCall(io_output(s, run_control_output_number(rc, s), PETSC_TRUE));
  s->output_step = PETSC_FALSE;
  rc->last_output_step = s->step;
  PetscFunctionReturn(0);
}

/* An output of the schedule (step 0 or an output time): the diagnostics due, which see
 * output_step, then the snapshot. */
static PetscErrorCode run_diagnose_and_output(sim *s, run_control *rc, PetscBool output) {
  PetscFunctionBeginUser;
  s->output_step = output;
  PetscCall(PetscLogEventBegin(events.diagnostics, 0, 0, 0, 0));
  PetscCall(diagnostics_sample(s));
  PetscCall(PetscLogEventEnd(events.diagnostics, 0, 0, 0, 0));
  if (output) {
    PetscCall(io_output(s, run_control_output_number(rc, s), run_control_at_end(s)));
    rc->last_output_step = s->step;
  }
  s->output_step = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* What every rank must decide alike after a step, in the loop's one reduction: a stop signal
 * that any rank got, and whether rank 0's wall clock calls for a progress line (the ranks'
 * clocks differ). */
static PetscErrorCode run_agree_after_step(const sim *s, const run_control *rc, int *stop_signal,
                                           PetscBool *progress_due) {
  int mine[2] = {stop_signal_pending(), s->rank == 0 && progress_wall_due(rc)}, all[2];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, s->comm));
  *stop_signal = all[0];
  *progress_due = all[1] ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode run_steps(dmhs_run *r) {
  sim *s = r->core;
  run_control *rc = &r->control;
  PetscInt n_owned_global, n_local = s->ps.n_owned;
  PetscBool stop; /* io: checkpoint at the interval; on a stop signal also stop */
  PetscBool progress_due;
  int stop_signal;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&n_local, &n_owned_global, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscCall(PetscLogStagePush(events.stage_steps));
  /* io: a restarted run already diagnosed and wrote out this state */
  if (!s->io->restarted)
    PetscCall(run_diagnose_and_output(s, rc, PETSC_TRUE));
  s->loop_start_wtime = MPI_Wtime();
  progress_start(s, rc);
  /* a signal during the setup stops here, with a checkpoint of the initial state */
  PetscCall(run_agree_after_step(s, rc, &stop_signal, &progress_due));
  PetscCall(io_after_step(s, stop_signal, &stop));
  /* stop at the step nearest t_end */
  while (!stop && s->t < s->t_end - 0.5 * s->dt) {
    PetscCall(
        timestep_before_step(s, &rc->ts)); /* the limits the state now sets: check or adapt dt */
    if (s->substeps.on)
      PetscCall(substep_mark_members(s)); /* the rows that move on the sub-steps */
    PetscCall(integrate_first_half(s));
    if (s->substeps.on)
      PetscCall(substep_solids(s)); /* the solids' sub-steps */
    timestep_advance(s);
    PetscCall(neighbours_update(s, s->force_rebuild));
    s->force_rebuild = PETSC_FALSE;
    PetscCall(sim_compute_forces(s));
    PetscCall(integrate_second_half_checked(s)); /* the second kick and the state check */
    for (int m = 0; m < s->n_modules; m++)
      if (s->modules[m]->post_step)
        PetscCall(s->modules[m]->post_step(s->modules[m], s));
    rc->particle_steps += n_owned_global;
    if (r->scn->post_step)
      PetscCall(r->scn->post_step(r->scn, s));
    const PetscBool output = run_control_output_due(rc, s);
    PetscCall(run_diagnose_and_output(s, rc, output));
    if (output)
      rc->next_output_t += rc->output_interval;
    PetscCall(run_agree_after_step(s, rc, &stop_signal, &progress_due));
    PetscCall(progress_after_step(s, rc, progress_due));
    PetscCall(io_after_step(s, stop_signal, &stop));
  }
  s->loop_seconds = MPI_Wtime() - s->loop_start_wtime;
  PetscCall(run_final_output(s, rc));
  PetscCall(PetscLogStagePop());
  PetscCall(diagnostics_finish(s));
  PetscCall(progress_summary(s, rc));
  PetscCall(dump_final(s));              /* mpi */
  PetscCall(migrate_report(&s->mig, s)); /* mpi */
  PetscCall(timestep_finish(&rc->ts));
  PetscCall(io_finish(s)); /* io: final checkpoint, run.json */
  PetscFunctionReturn(0);
}

PetscErrorCode sim_destroy(sim **sp) {
  sim *s = *sp;
  PetscFunctionBeginUser;
  if (!s)
    PetscFunctionReturn(0);
  PetscCall(diagnostics_destroy(s)); /* first: they may hold modules and the scene's data */
  for (int m = 0; m < s->n_modules; m++) {
    if (s->modules[m]->destroy)
      PetscCall(s->modules[m]->destroy(s->modules[m]));
    PetscCall(PetscFree(s->modules[m]));
  }
  PetscCall(io_destroy(s));
  PetscCall(topology_destroy(&s->topo)); /* solids */
  PetscCall(halo_destroy(&s->hal));
  PetscCall(partition_destroy(&s->part)); /* mpi */
  PetscCall(cells_destroy(&s->cel));
  PetscCall(particles_destroy(&s->ps));
  PetscCall(registry_finalize());
  options_forget();
  PetscCall(PetscFree(s->io));
  PetscCall(PetscFree(*sp));
  PetscFunctionReturn(0);
}

PetscErrorCode run_destroy(dmhs_run **rp) {
  PetscFunctionBeginUser;
  if (!*rp)
    PetscFunctionReturn(0);
  dmhs_run *r = *rp;
  PetscCall(
      sim_destroy(&r->core)); /* first: its diagnostics and modules may hold the scene's data */
  if (r->scn) {
    if (r->scn->destroy)
      PetscCall(r->scn->destroy(r->scn));
    PetscCall(PetscFree(r->scn));
  }
  PetscCall(PetscFree(*rp));
  PetscFunctionReturn(0);
}
