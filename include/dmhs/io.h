/* Output, checkpoints, restart and the run record (src/io/io.c): the glue the
 * step loop calls. Options (-output_snapshots, -checkpoint_interval,
 * -checkpoint_at_end, -restart) are read in one options pass; snapshots and
 * the XDMF index are written at every output time and at the end,
 * checkpoints at an interval, at the end and when SIGTERM / SIGINT / SIGUSR1
 * arrives; <output_dir>/run.json records version, commit, options, rank
 * count, host and pid, start/end time, a heartbeat, the exit status and, at the
 * end, the halo's sizes over the ranks. */
#ifndef DMHS_IO_H
#define DMHS_IO_H
#include <petscsys.h>
#include "dmhs/halo.h"

struct sim;
struct xdmf;

/* An attribute that a module adds to the root of every snapshot (io_snapshot_attribute_*): the
 * SPH module's kernel and support radius, so that post-processing reads them instead of
 * knowing each scene's defaults. */
#define IO_SNAPSHOT_ATTRIBUTES 8
typedef struct io_attribute {
  char name[32];
  char text[32]; /* a string attribute, or "" for a real one */
  double value;
} io_attribute;

/* A value of an upper layer that checkpoints keep and a restart gives back
 * (io_checkpoint_keep_real): the driver's next output and progress times. */
#define IO_KEPT_REALS 4
typedef struct io_kept_real {
  const char *name; /* the checkpoint's attribute */
  double *value;
} io_kept_real;

typedef struct io_state {
  /* options */
  PetscBool snapshots;                   /* -output_snapshots */
  PetscInt snapshot_every;               /* -snapshot_every: a snapshot at every Nth output */
  double checkpoint_interval;            /* -checkpoint_interval [s], 0 = never */
  PetscBool checkpoint_at_end;           /* -checkpoint_at_end */
  char restart_file[PETSC_MAX_PATH_LEN]; /* -restart, "" = fresh start */
  PetscBool restart_allow_change;        /* -restart_allow_change: physics options may differ */
  char *restart_changes;                 /* what differed from the checkpoint's options, or NULL */
  char *restart_new_options; /* options the checkpoint's dmhs lacked, at their defaults, or NULL */
  /* state */
  PetscBool restarted;                 /* the state was read from restart_file */
  double dt_options;                   /* the options' dt, which a restart replaces by its own */
  double restart_t;                    /* t when this session's step loop started [s] */
  PetscInt snapshot_index;             /* number of the next snapshot file */
  double next_checkpoint_t;            /* [s] */
  PetscInt last_checkpoint_step;       /* -1 = none written by this session */
  int stop_signal;                     /* signal that stopped the run, 0 = none */
  struct xdmf *xdmf;                   /* rank 0: the snapshots indexed so far */
  char *options;                       /* resolved options (PetscOptionsGetAll) */
  char start_time[32];                 /* ISO 8601, UTC */
  char previous_status[32];            /* status in the run.json this run replaced ("" = none) */
  char host[256];                      /* rank 0's host name (run.json) */
  char executable[PETSC_MAX_PATH_LEN]; /* rank 0's program file (run.json), or "" */
  double heartbeat_interval;           /* [s] the next heartbeat comes within this (0: unknown) */
  PetscBool heartbeat_failed;          /* the last heartbeat could not be written (said then) */
  PetscBool run_json_started;
  PetscBool halo_known; /* halo holds the sizes of the last build (the run reached its end) */
  halo_stats halo;      /* run.json "halo" */
  /* csv_open after a restart keeps the rows at the checkpoint's time (those of a diagnostic
   * that sampled there; set around each sample by the diagnostics list) */
  PetscBool csv_keep_restart_rows;
  io_attribute snapshot_attributes[IO_SNAPSHOT_ATTRIBUTES]; /* the modules' (see above) */
  int n_snapshot_attributes;
  char output_dir[PETSC_MAX_PATH_LEN]; /* where every file goes (io_set_output_dir) */
  io_kept_real kept[IO_KEPT_REALS];    /* the callers' values a checkpoint keeps */
  int n_kept;
} io_state;

/* The directory every output file of the run goes to; the driver creates it first. */
PetscErrorCode io_set_output_dir(struct sim *s, const char *dir);
/* A checkpoint keeps *value under name, and a restart (io_restart_read) sets *value from it. */
PetscErrorCode io_checkpoint_keep_real(struct sim *s, const char *name, double *value);
/* <output_dir>/<name>: where every output file of the run goes. */
PetscErrorCode io_output_path(const struct sim *s, const char *name, char *path, size_t len);
/* Options pass; also called for -help. Must run before the scene is built. */
PetscErrorCode io_set_from_options(struct sim *s);
/* After the output directory exists: run.json ("running"), signal handlers. */
PetscErrorCode io_setup(struct sim *s);
/* The restart sequence, in the driver's order: io_restart_read, the driver's neighbour
 * rebuild and state check, io_restart_continue.
 * With -restart: replaces the particle state, step, t, dt, module state and the values kept
 * (io_checkpoint_keep_real) by the checkpoint's (a and drho too: the next kick uses them, no
 * force evaluation); refuses a -t_end not after it. No-op otherwise. */
PetscErrorCode io_restart_read(struct sim *s);
/* After a restart's neighbour rebuild: says where the run continues, removes the snapshots
 * written after the checkpoint and indexes those before it; in any run, the session's start
 * time and the next checkpoint time. */
PetscErrorCode io_restart_continue(struct sim *s);
/* At an output time (and t = 0): snapshot + XDMF index, unless -output_snapshots false or
 * the output's number (the driver's: t / output_interval, the same across a restart) is not
 * a multiple of -snapshot_every; the run's last output (last) always writes one. */
PetscErrorCode io_output(struct sim *s, PetscInt64 output_number, PetscBool last);
/* After every step (and before the first), on every rank: checkpoint at the interval or on a
 * stop signal (stop_signal.h); any_signal is the one any rank got (the step loop reduced
 * stop_signal_pending() over the ranks), 0 if none: then *stop, and run.json says
 * "signal-checkpoint". */
PetscErrorCode io_after_step(struct sim *s, int any_signal, PetscBool *stop);
/* Rank 0 rewrites run.json ("running") with the time of now as its heartbeat: the run is
 * alive. A write that fails is said once and does not stop the run. */
PetscErrorCode io_heartbeat(struct sim *s);
/* The end checkpoint (-checkpoint_at_end), unless one was written at this step. */
PetscErrorCode io_checkpoint_at_end(struct sim *s);
/* After the loop: final checkpoint (-checkpoint_at_end), run.json with the exit status. */
PetscErrorCode io_finish(struct sim *s);
PetscErrorCode io_destroy(struct sim *s);
/* Adds (or replaces) a root attribute of every snapshot written from now on: a real number
 * (one-element array, like time) or a string. Any rank may call it; every rank must give the
 * same value. */
PetscErrorCode io_snapshot_attribute_real(struct sim *s, const char *name, double value);
PetscErrorCode io_snapshot_attribute_string(struct sim *s, const char *name, const char *text);
/* Error path (best effort, never fails): run.json gets status "error" and the message. */
void io_record_error(struct sim *s, const char *message);

#endif
