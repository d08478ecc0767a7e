/* Output, checkpoints, restart and the run record: the glue between the step
 * loop (run_steps, src/driver/run.c) and snapshot.c, xdmf.c, checkpoint.c.
 *
 * Signals: SIGTERM, SIGINT and SIGUSR1 (what batch systems, timeout, mpirun and
 * Ctrl-C send) only set a flag (stop_signal.c, which also says when a repeat
 * kills); after every step, and before the first, the ranks agree on it with
 * one MPI_Allreduce (the step loop's, src/driver/run.c: a signal any one rank
 * got stops them all), write a checkpoint, record "signal-checkpoint" in
 * run.json and stop cleanly.
 *
 * run.json (rank 0, rewritten atomically): dmhs_version, commit (build_info.h),
 * scene, ranks, host, pid and executable (rank 0's), options, restart_from, start, end,
 * heartbeat (ISO 8601 UTC: the time of this write; a live run writes one at
 * every progress line and checkpoint) and heartbeat_interval (the wall seconds
 * within which the next comes, or null), status ("running", "completed",
 * "signal-checkpoint", "error"), step, t, checkpoint, message, previous_status
 * (the status in the run.json this run replaced: "running" there means that run
 * was killed, or is still going) and, once the step loop has ended, halo (the
 * sizes of the last neighbour build over the ranks: halo_stats.c). "running"
 * with a pid gone from its host, or a heartbeat older than two intervals, is a
 * run that died (scripts/run_state.sh). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/checkpoint.h"
#include "dmhs/snapshot.h"
#include "dmhs/xdmf.h"
#include "dmhs/migrate.h"
#include "dmhs/stop_signal.h"
#include "dmhs/build_info.h"
#include "h5check.h"
#include "dmhs/outdir.h"

PetscErrorCode io_set_output_dir(sim *s, const char *dir) {
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(s->io->output_dir, dir, sizeof(s->io->output_dir)));
  PetscFunctionReturn(0);
}

PetscErrorCode io_checkpoint_keep_real(sim *s, const char *name, double *value) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  PetscCheck(io->n_kept < IO_KEPT_REALS, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "io_checkpoint_keep_real: more than %d values", IO_KEPT_REALS);
  io->kept[io->n_kept++] = (io_kept_real){name, value};
  PetscFunctionReturn(0);
}

PetscErrorCode io_set_from_options(sim *s) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  io->snapshots = PETSC_TRUE;
  io->snapshot_every = 1;
  io->checkpoint_at_end = PETSC_TRUE;
  io->last_checkpoint_step = -1;
  io->csv_keep_restart_rows = PETSC_TRUE;
  PetscOptionsBegin(s->comm, NULL, "Output, checkpoints and restart", NULL);
  PetscCall(options_read_bool(
      "-output_snapshots",
      "Write <output_dir>/snap_NNNNNN.h5 and particles.xdmf at every -output_interval", NULL,
      io->snapshots, &io->snapshots, NULL));
  PetscCall(options_run_control("-output_snapshots"));
  PetscCall(options_read_int("-snapshot_every",
                             "Write a snapshot at every Nth output time only (and at the "
                             "run's last step) [1]",
                             NULL, io->snapshot_every, &io->snapshot_every, NULL));
  PetscCall(options_run_control("-snapshot_every"));
  PetscCall(options_read_real(
      "-checkpoint_interval",
      "Physical time between checkpoints to <output_dir>/checkpoint.h5 [s] (0 = never)", NULL,
      io->checkpoint_interval, &io->checkpoint_interval, NULL));
  PetscCall(options_run_control("-checkpoint_interval"));
  PetscCall(options_read_bool("-checkpoint_at_end",
                              "Write <output_dir>/checkpoint.h5 when the run reaches -t_end", NULL,
                              io->checkpoint_at_end, &io->checkpoint_at_end, NULL));
  PetscCall(options_run_control("-checkpoint_at_end"));
  PetscCall(options_read_string(
      "-restart", "Continue from this checkpoint file (same scene and options)", NULL,
      io->restart_file, io->restart_file, sizeof(io->restart_file), NULL));
  PetscCall(options_run_control("-restart"));
  PetscCall(options_read_bool(
      "-restart_allow_change",
      "Let -restart continue with physics options that differ from the checkpoint's "
      "(listed in run.json)",
      NULL, io->restart_allow_change, &io->restart_allow_change, NULL));
  PetscCall(options_run_control("-restart_allow_change"));
  PetscOptionsEnd();
  PetscCheck(io->snapshot_every >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-snapshot_every must be >= 1 (got %" PetscInt_FMT ")", io->snapshot_every);
  PetscCheck(io->checkpoint_interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-checkpoint_interval must be >= 0 (got %g; 0 = never)", io->checkpoint_interval);
  PetscFunctionReturn(0);
}

/* ---- run.json ---------------------------------------------------------- */

static void io_now_iso(char *buf, size_t len) {
  time_t now = time(NULL);
  struct tm tm;
  gmtime_r(&now, &tm);
  strftime(buf, len, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

static void io_json_string(FILE *f, const char *v) {
  fputc('"', f);
  for (const unsigned char *c = (const unsigned char *)(v ? v : ""); *c; c++) {
    if (*c == '"' || *c == '\\')
      fprintf(f, "\\%c", *c);
    else if (*c < 0x20)
      fprintf(f, "\\u%04x", *c);
    else
      fputc(*c, f);
  }
  fputc('"', f);
}

/* v as a JSON string, or null when v is NULL or empty */
static void io_json_string_or_null(FILE *f, const char *v) {
  if (v && v[0])
    io_json_string(f, v);
  else
    fprintf(f, "null");
}

/* Writes text to path through path.tmp and a rename; when that fails (disk
 * full: no room for a second copy) the old file is overwritten in place, its
 * blocks already allocated, padded with blanks to its old length. 0 or an errno. */
static int io_replace_file(const char *path, const char *text) {
  char tmp[PETSC_MAX_PATH_LEN + 24];
  const size_t len = strlen(text);
  snprintf(tmp, sizeof(tmp), "%s.tmp", path);
  FILE *f = fopen(tmp, "w");
  int failed = !f;
  if (f) {
    failed = fwrite(text, 1, len, f) != len;
    failed = fclose(f) != 0 || failed;
  }
  if (!failed && !rename(tmp, path))
    return 0;
  const int err = errno ? errno : EIO;
  unlink(tmp);
  f = fopen(path, "r+");
  if (!f)
    return err;
  fseek(f, 0, SEEK_END);
  const long old = ftell(f);
  rewind(f);
  failed = fwrite(text, 1, len, f) != len;
  for (long k = (long)len; k < old && !failed; k++)
    failed = fputc(' ', f) == EOF;
  failed = fclose(f) != 0 || failed;
  return failed ? err : 0;
}

static void io_json_count(FILE *f, const char *name, const halo_count *c, int ranks, int last) {
  fprintf(f, "    \"%s\": {\"min\": %lld, \"mean\": %.9g, \"max\": %lld, \"total\": %lld}%s\n",
          name, (long long)c->min, (double)c->total / ranks, (long long)c->max, (long long)c->total,
          last ? "" : ",");
}

/* Counts are integers; means are total / ranks. */
static void io_json_halo(FILE *f, const halo_stats *h) {
  /* one rank: the periodic images are copied row to row */
  fprintf(f, ",\n  \"halo\": {\n    \"exchange\": \"%s\",\n",
          h->ranks > 1 ? "MPI_Alltoallv" : "local copies");
  fprintf(f, "    \"ghost_bytes\": %lld,\n", (long long)h->ghost_bytes);
  io_json_count(f, "owned", &h->owned, h->ranks, 0);
  io_json_count(f, "ghost", &h->ghost, h->ranks, 0);
  io_json_count(f, "remote_ghost", &h->remote, h->ranks, 0);
  io_json_count(f, "sent", &h->sent, h->ranks, 0);
  io_json_count(f, "partners", &h->partners, h->ranks, 0);
  io_json_count(f, "forward_bytes", &h->forward_bytes, h->ranks, 1);
  fprintf(f, "  }");
}

/* Plain C (no PETSc calls): also used on the error path. Returns 0 or an errno. */
static int io_write_run_json(const sim *s, const char *status, const char *message, int ended) {
  char path[PETSC_MAX_PATH_LEN + 16], now[32], checkpoint[PETSC_MAX_PATH_LEN + 16], *text = NULL;
  size_t text_len = 0;
  snprintf(path, sizeof(path), "%s/run.json", s->io->output_dir);
  snprintf(checkpoint, sizeof(checkpoint), "%s/checkpoint.h5", s->io->output_dir);
  FILE *f = open_memstream(&text, &text_len);
  if (!f)
    return errno ? errno : ENOMEM;
  fprintf(f, "{\n  \"dmhs_version\": ");
  io_json_string(f, DMHS_VERSION);
  fprintf(f, ",\n  \"commit\": ");
  io_json_string(f, dmhs_commit);
  fprintf(f, ",\n  \"scene\": ");
  io_json_string(f, s->scene_name);
  fprintf(f, ",\n  \"ranks\": %d,\n  \"host\": ", (int)s->size);
  io_json_string(f, s->io->host);
  fprintf(f, ",\n  \"pid\": %ld,\n  \"executable\": ", (long)getpid());
  io_json_string_or_null(f, s->io->executable);
  fprintf(f, ",\n  \"options\": ");
  io_json_string(f, s->io->options);
  fprintf(f, ",\n  \"restart_from\": ");
  io_json_string_or_null(f, s->io->restart_file);
  if (s->io->restart_file[0]) {
    fprintf(f, ",\n  \"restart_allow_change\": %s,\n  \"restart_changes\": ",
            s->io->restart_allow_change ? "true" : "false");
    io_json_string_or_null(f, s->io->restart_changes);
    fprintf(f, ",\n  \"restart_new_options\": ");
    io_json_string_or_null(f, s->io->restart_new_options);
  }
  fprintf(f, ",\n  \"previous_status\": ");
  io_json_string_or_null(f, s->io->previous_status);
  fprintf(f, ",\n  \"start\": ");
  io_json_string(f, s->io->start_time);
  io_now_iso(now, sizeof(now));
  fprintf(f, ",\n  \"end\": ");
  if (ended)
    io_json_string(f, now);
  else
    fprintf(f, "null");
  fprintf(f, ",\n  \"heartbeat\": ");
  io_json_string(f, now);
  fprintf(f, ",\n  \"heartbeat_interval\": ");
  if (s->io->heartbeat_interval > 0)
    fprintf(f, "%.17g", s->io->heartbeat_interval);
  else
    fprintf(f, "null");
  fprintf(f, ",\n  \"status\": ");
  io_json_string(f, status);
  fprintf(f, ",\n  \"step\": %lld,\n  \"t\": %.17g,\n  \"checkpoint\": ", (long long)s->step, s->t);
  if (s->io->last_checkpoint_step >= 0)
    io_json_string(f, checkpoint);
  else
    fprintf(f, "null");
  if (s->io->halo_known)
    io_json_halo(f, &s->io->halo);
  if (message) {
    fprintf(f, ",\n  \"message\": ");
    io_json_string(f, message);
  }
  int failed = fprintf(f, "\n}\n") < 0;
  failed = fclose(f) != 0 || failed;
  const int err = failed ? ENOMEM : io_replace_file(path, text);
  free(text);
  return err;
}

static PetscErrorCode io_run_json(sim *s, const char *status, PetscBool ended) {
  PetscFunctionBeginUser;
  if (s->rank == 0) {
    const int err = io_write_run_json(s, status, NULL, ended);
    PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s/run.json: %s",
               s->io->output_dir, strerror(err));
  }
  PetscFunctionReturn(0);
}

/* A heartbeat that cannot be written (a full disk) is said once; the run goes on, and a
 * checkpoint or snapshot that cannot be written stops it. */
PetscErrorCode io_heartbeat(sim *s) {
  PetscFunctionBeginUser;
  if (s->rank != 0)
    PetscFunctionReturn(0);
  const int err = io_write_run_json(s, "running", NULL, 0);
  if (err && !s->io->heartbeat_failed)
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR,
                           "dmhs: warning: cannot update %s/run.json (its heartbeat): %s; the run "
                           "goes on\n",
                           s->io->output_dir, strerror(err)));
  s->io->heartbeat_failed = err ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

void io_record_error(sim *s, const char *message) {
  if (!s || s->rank != 0 || !s->io->run_json_started)
    return;
  /* a write the error interrupted (disk full) leaves its temporary file */
  (void)outdir_remove_tmp(s->io->output_dir);
  (void)io_write_run_json(s, "error", message && message[0] ? message : "see the error on stderr",
                          1);
}

/* ---- setup, restart ------------------------------------------------------ */

/* The "status" of an existing <dir>/run.json, or "" (plain C). */
static void io_previous_status(const char *dir, char *status, size_t len) {
  char path[PETSC_MAX_PATH_LEN + 16], text[8192];
  const char *key = "\"status\": \"";
  status[0] = 0;
  snprintf(path, sizeof(path), "%s/run.json", dir);
  FILE *f = fopen(path, "r");
  if (!f)
    return;
  const size_t n = fread(text, 1, sizeof(text) - 1, f);
  fclose(f);
  text[n] = 0;
  const char *at = strstr(text, key), *end = at ? strchr(at + strlen(key), '"') : NULL;
  if (at && end && (size_t)(end - at - strlen(key)) < len)
    snprintf(status, len, "%.*s", (int)(end - at - strlen(key)), at + strlen(key));
}

PetscErrorCode io_setup(sim *s) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  PetscCall(h5check_quiet());
  PetscCall(PetscOptionsGetAll(NULL, &io->options));
  io_now_iso(io->start_time, sizeof(io->start_time));
  if (s->rank == 0 && gethostname(io->host, sizeof(io->host)) != 0)
    PetscCall(PetscSNPrintf(io->host, sizeof(io->host), "unknown")); /* run.json says so */
  io->host[sizeof(io->host) - 1] = 0;
  if (s->rank == 0) { /* which program the pid is (scripts/run_state.sh): Linux names it here */
    const ssize_t n = readlink("/proc/self/exe", io->executable, sizeof(io->executable) - 1);
    io->executable[n > 0 ? n : 0] = 0;
  }
  if (s->rank == 0)
    io_previous_status(s->io->output_dir, io->previous_status, sizeof(io->previous_status));
  PetscCall(io_run_json(s, "running", PETSC_FALSE));
  io->run_json_started = PETSC_TRUE;
  if (s->rank == 0)
    PetscCall(xdmf_create(&io->xdmf));
  /* normally in place since run_create began: a signal during the setup waits for step 0 */
  PetscCall(stop_signal_install(s->rank));
  PetscFunctionReturn(0);
}

PetscErrorCode io_restart_read(sim *s) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  if (io->restart_file[0]) {
    io->dt_options = s->dt;
    PetscCall(checkpoint_read(s, io->restart_file));
    PetscCheck(
        s->t_end > s->t + 0.5 * s->dt, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
        "-t_end %g s is not after the time of the checkpoint %s (t = %.9g s, step %" PetscInt_FMT
        "): nothing to run; give a later -t_end",
        s->t_end, io->restart_file, s->t, s->step);
    if ((io->restart_changes || io->restart_new_options) && s->rank == 0) {
      /* run.json ("running") records what changed from the start */
      const int err = io_write_run_json(s, "running", NULL, 0);
      PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s/run.json: %s",
                 s->io->output_dir, strerror(err));
    }
    io->restarted = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode io_restart_continue(sim *s) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  if (io->restarted) {
    PetscCall(PetscPrintf(
        s->comm, "Restarted from %s at step %" PetscInt_FMT ", t = %.9g s, dt = %g s%s\n",
        io->restart_file, s->step, s->t, s->dt,
        s->dt != io->dt_options ? " (the checkpoint's dt, not the one from the options)" : ""));
    if (s->rank == 0) {
      /* the snapshots the interrupted run wrote after its checkpoint are written again */
      const int n = outdir_remove_snapshots(s->io->output_dir, (long)io->snapshot_index);
      if (n)
        PetscCall(PetscPrintf(
            PETSC_COMM_SELF,
            "output directory %s: removed %d snapshot file(s) written after the checkpoint\n",
            s->io->output_dir, n));
    }
    if (s->rank == 0 && io->snapshots) {
      /* index the snapshots the interrupted run had written before the checkpoint */
      PetscCall(xdmf_scan(io->xdmf, s->io->output_dir, io->snapshot_index));
    }
  }
  io->restart_t = s->t;
  if (io->checkpoint_interval > 0) {
    const double k = PetscFloorReal((s->t + 0.5 * s->dt) / io->checkpoint_interval);
    io->next_checkpoint_t = (k + 1) * io->checkpoint_interval;
  }
  PetscFunctionReturn(0);
}

/* ---- during the run ------------------------------------------------------ */

PetscErrorCode io_output(sim *s, PetscInt64 output_number, PetscBool last) {
  io_state *io = s->io;
  char name[64], path[PETSC_MAX_PATH_LEN];
  PetscInt64 n, n_bonds;
  PetscFunctionBeginUser;
  if (!io->snapshots)
    PetscFunctionReturn(0);
  if (io->snapshot_every > 1 && !last && output_number % io->snapshot_every != 0)
    PetscFunctionReturn(0);
  PetscCall(snapshot_write(s, io->snapshot_index, &n, &n_bonds));
  if (s->rank == 0) {
    const xdmf_connectivity bonds = {"/bonds/rows", n_bonds, 2, "bonds"};
    PetscCall(snapshot_name(io->snapshot_index, name, sizeof(name)));
    PetscCall(xdmf_add(io->xdmf, name, s->t, n, n_bonds > 0 ? &bonds : NULL));
    PetscCall(io_output_path(s, "particles.xdmf", path, sizeof(path)));
    PetscCall(xdmf_write(io->xdmf, path));
  }
  io->snapshot_index++;
  PetscFunctionReturn(0);
}

static PetscErrorCode io_checkpoint(sim *s) {
  char path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(io_output_path(s, "checkpoint.h5", path, sizeof(path)));
  PetscCall(checkpoint_write(s, path));
  s->io->last_checkpoint_step = s->step;
  PetscCall(io_heartbeat(s)); /* run.json names the checkpoint */
  PetscFunctionReturn(0);
}

PetscErrorCode io_after_step(sim *s, int any, PetscBool *stop) {
  io_state *io = s->io;
  PetscBool due = PETSC_FALSE;
  PetscFunctionBeginUser;
  *stop = PETSC_FALSE;
  if (io->checkpoint_interval > 0 && s->t >= io->next_checkpoint_t - 0.5 * s->dt) {
    due = PETSC_TRUE;
    while (io->next_checkpoint_t <= s->t + 0.5 * s->dt)
      io->next_checkpoint_t += io->checkpoint_interval;
  }
  if (due || any)
    PetscCall(io_checkpoint(s));
  if (any) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(io_output_path(s, "checkpoint.h5", path, sizeof(path)));
    io->stop_signal = any;
    *stop = PETSC_TRUE;
    /* recorded at once: a further signal may now kill the run (stop_signal.c) */
    PetscCall(io_run_json(s, "signal-checkpoint", PETSC_FALSE));
    stop_signal_checkpoint_written();
    PetscCall(PetscPrintf(s->comm,
                          "dmhs: received %s: stopped at step %" PetscInt_FMT
                          ", t = %.9g s after writing the "
                          "checkpoint %s; continue with -restart %s\n",
                          stop_signal_name(any), s->step, s->t, path, path));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode io_checkpoint_at_end(sim *s) {
  PetscFunctionBeginUser;
  if (s->io->checkpoint_at_end && s->io->last_checkpoint_step != s->step)
    PetscCall(io_checkpoint(s));
  PetscFunctionReturn(0);
}

PetscErrorCode io_finish(sim *s) {
  io_state *io = s->io;
  PetscFunctionBeginUser;
  PetscCall(io_checkpoint_at_end(s));
  PetscCall(
      halo_stats_gather(&s->hal, &s->ps, s->ghost_step_fields, s->n_ghost_step_fields, &io->halo));
  io->halo_known = PETSC_TRUE;
  PetscCall(io_run_json(s, io->stop_signal ? "signal-checkpoint" : "completed", PETSC_TRUE));
  PetscFunctionReturn(0);
}

static PetscErrorCode io_snapshot_attribute(sim *s, const char *name, const char *text,
                                            double value) {
  io_state *io = s->io;
  int k = 0;
  PetscFunctionBeginUser;
  PetscCheck(strlen(name) < sizeof(io->snapshot_attributes[0].name) &&
                 strlen(text) < sizeof(io->snapshot_attributes[0].text),
             PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "snapshot attribute %s: name or text too long",
             name);
  while (k < io->n_snapshot_attributes && strcmp(io->snapshot_attributes[k].name, name))
    k++;
  PetscCheck(k < IO_SNAPSHOT_ATTRIBUTES, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "snapshot attribute %s: more than %d attributes", name, IO_SNAPSHOT_ATTRIBUTES);
  if (k == io->n_snapshot_attributes)
    io->n_snapshot_attributes++;
  io_attribute *a = &io->snapshot_attributes[k];
  PetscCall(PetscStrncpy(a->name, name, sizeof(a->name)));
  PetscCall(PetscStrncpy(a->text, text, sizeof(a->text)));
  a->value = value;
  PetscFunctionReturn(0);
}

PetscErrorCode io_snapshot_attribute_real(sim *s, const char *name, double value) {
  PetscFunctionBeginUser;
  PetscCall(io_snapshot_attribute(s, name, "", value));
  PetscFunctionReturn(0);
}

PetscErrorCode io_snapshot_attribute_string(sim *s, const char *name, const char *text) {
  PetscFunctionBeginUser;
  PetscCheck(text[0], PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "snapshot attribute %s: an empty string", name);
  PetscCall(io_snapshot_attribute(s, name, text, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode io_destroy(sim *s) {
  PetscFunctionBeginUser;
  if (!s->io) /* a core state built without the driver (tests) */
    PetscFunctionReturn(0);
  PetscCall(PetscFree(s->io->options));
  PetscCall(PetscFree(s->io->restart_changes));
  PetscCall(PetscFree(s->io->restart_new_options));
  PetscCall(xdmf_destroy(&s->io->xdmf));
  PetscFunctionReturn(0);
}
