/* dmhs: Discrete Multi-Hybrid System solver (SPH liquid + mass-spring solids).
 * PetscInitialize -> run_create -> run_steps -> run_destroy -> PetscFinalize. */
#include <string.h>
#include <strings.h>
#include "dmhs/run.h"
#include "dmhs/io.h"
#include "dmhs/options_files.h"
#include "dmhs/console_log.h"

static const char help[] =
    "dmhs: SPH liquid coupled with mass-spring solids (Discrete Multi-Hybrid System).\n"
    "Usage: mpirun -n N dmhs -options_file input/<case>.opts [-option value ...]\n"
    "Every option is listed below once, with its value and unit.\n\n";

static char first_error[512]; /* for run.json (io_record_error) */
static PetscBool trace;       /* -dmhs_traceback on the command line */

/* A user sees the one line that names the option, file or particle at fault;
 * where in the source it was raised, and through which calls, only with
 * -dmhs_traceback (after PetscInitialize, PETSc's own full traceback). */
static PetscErrorCode dmhs_error_handler(MPI_Comm comm, int line, const char *func,
                                         const char *file, PetscErrorCode n, PetscErrorType p,
                                         const char *mess, void *ctx) {
  (void)comm;
  (void)ctx;
  if (p == PETSC_ERROR_INITIAL) {
    char text[2048];
    int rank = 0, mpi_up = 0;
    MPI_Initialized(&mpi_up);
    if (mpi_up)
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    char out[2200];
    options_files_explain(mess ? mess : "(no message)", text, sizeof(text));
    snprintf(out, sizeof(out), "dmhs: error%s%.0d: %s\n", rank ? " on rank " : "", rank, text);
    fputs(out, stderr);
    console_log_add_line(out); /* dmhs.log, when rank 0's is open */
    if (trace) {
      snprintf(out, sizeof(out), "dmhs:   (raised in %s() at %s:%d)\n", func, file, line);
      fputs(out, stderr);
      console_log_add_line(out);
    }
    if (!first_error[0])
      snprintf(first_error, sizeof(first_error), "%.511s", text);
    fflush(stderr);
  } else if (trace) {
    char out[512];
    snprintf(out, sizeof(out), "dmhs:   (called from %s() at %s:%d)\n", func, file, line);
    fputs(out, stderr);
    console_log_add_line(out);
    fflush(stderr);
  }
  return n;
}

/* -dmhs_traceback on the command line, read before PETSc is (its errors too get the trace):
 * alone or followed by an option, or with true/yes/on/1. */
static PetscBool traceback_asked(int argc, char **argv) {
  PetscBool on = PETSC_FALSE;
  for (int k = 1; k < argc; k++)
    if (!strcmp(argv[k], "-dmhs_traceback")) {
      const char *v = k + 1 < argc ? argv[k + 1] : "-";
      on = v[0] == '-' || !strcasecmp(v, "true") || !strcasecmp(v, "yes") || !strcasecmp(v, "on") ||
                   !strcmp(v, "1")
               ? PETSC_TRUE
               : PETSC_FALSE;
    }
  return on;
}

/* An option is "-" followed by a letter (a negative number such as -1e-3 is
 * a value). PETSc silently drops a word that is neither an option nor the
 * value right after one (`-sph_nu 1e-6 1e-7`, or a shell-split value), so
 * such a run would go on with a default the user meant to change. */
static int is_option_word(const char *w) {
  return w[0] == '-' &&
         ((w[1] >= 'a' && w[1] <= 'z') || (w[1] >= 'A' && w[1] <= 'Z') || w[1] == '-');
}

static int stray_argument(int argc, char **argv) {
  for (int k = 1; k < argc; k++)
    if (!is_option_word(argv[k]) && (k == 1 || !is_option_word(argv[k - 1])))
      return k;
  return 0;
}

int main(int argc, char **argv) {
  dmhs_run *r = NULL;
  PetscBool help_only = PETSC_FALSE, traceback = PETSC_FALSE;
  PetscErrorCode ierr;
  PetscMPIInt size;
  /* installed before PetscInitialize, so that an error reading the options (a
   * missing or malformed -options_file) is one line too; never popped: it was
   * allocated before PETSc's tracing allocator, which must not free it */
  PetscPushErrorHandler(dmhs_error_handler, NULL);
  const int stray = stray_argument(argc, argv);
  if (stray) {
    fprintf(
        stderr,
        "dmhs: error: stray argument '%s' (word %d of the command line): every value must follow "
        "its -option\n",
        argv[stray], stray);
    return 1;
  }
  /* -help: dmhs lists its own options (run_create); PETSc would add its banner,
   * its generic options and every section again, so it does not see it */
  int kept = 1;
  for (int k = 1; k < argc; k++) {
    if (!strcmp(argv[k], "-help") || !strcmp(argv[k], "--help"))
      help_only = PETSC_TRUE;
    else
      argv[kept++] = argv[k];
  }
  argc = kept;
  argv[argc] = NULL;
  trace = traceback_asked(argc, argv);
  /* nested options files from the including file's directory (options_files.h) */
  if (options_files_resolve(&argc, &argv)) {
    fprintf(stderr, "dmhs: error: out of memory reading the options files\n");
    return 1;
  }
  ierr = PetscInitialize(&argc, &argv, NULL, help);
  if (ierr) {
    int mpi_up = 0;
    MPI_Initialized(&mpi_up);
    if (mpi_up) {
      /* the other ranks may wait for rank 0's options: only an abort frees them */
      MPI_Comm_size(MPI_COMM_WORLD, &size);
      if (size > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      MPI_Finalize();
    }
    options_files_free();
    return 1;
  }
  /* rank 0's console, copied into <output_dir>/dmhs.log once that exists (run_create) */
  PetscCall(console_log_start(PETSC_COMM_WORLD));
  PetscCall(options_get_bool(NULL, NULL, "-dmhs_traceback", &traceback, NULL));
  if (traceback)
    PetscCall(PetscPushErrorHandler(PetscTraceBackErrorHandler, NULL));
  if (help_only)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", help));
  ierr = run_create(PETSC_COMM_WORLD, &r, &help_only);
  if (!ierr && !help_only)
    ierr = run_steps(r);
  if (ierr) {
    io_record_error(r ? r->core : NULL, first_error); /* run.json: status "error" (best effort) */
    /* one rank alone can fail (a particle's NaN): only an abort frees the others */
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    if (size > 1)
      MPI_Abort(PETSC_COMM_WORLD, 1);
    PetscCall(PetscFinalize());
    console_log_stop();
    options_files_free();
    return 1;
  }
  PetscCall(run_destroy(&r));
  if (traceback)
    PetscCall(PetscPopErrorHandler());
  PetscCall(PetscFinalize()); /* -log_view prints here: still copied to dmhs.log */
  console_log_stop();
  options_files_free();
  return 0;
}
