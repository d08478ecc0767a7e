/* <output_dir>/dmhs.log, the copy of rank 0's console: see console_log.h. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "dmhs/build_info.h"
#include "dmhs/console_log.h"

typedef PetscErrorCode (*console_printer)(FILE *, const char[], va_list);

static console_printer console_log_previous; /* PETSc's printer (or whoever was there) */
static FILE *console_log_file;               /* once the output directory exists */
static char console_log_path[PETSC_MAX_PATH_LEN + 16];
static char *console_log_early; /* printed before the file opened */
static size_t console_log_early_len, console_log_early_cap;
static int console_log_early_dropped; /* past CONSOLE_LOG_EARLY_MAX */
static int console_log_failed;        /* a write failed: no copy from then on */

/* Ends the copy after a failed write, saying so once (not through PETSc: this runs inside
 * its printer). */
static void console_log_fail(int err) {
  if (console_log_failed)
    return;
  console_log_failed = 1;
  fprintf(stderr, "dmhs: warning: cannot write %s (%s): the console is no longer copied there\n",
          console_log_path, strerror(err ? err : EIO));
  fflush(stderr);
  if (console_log_file)
    fclose(console_log_file);
  console_log_file = NULL;
}

/* Into the file, flushed (a killed run loses nothing it printed). */
static void console_log_write(const char *text, size_t len) {
  errno = 0;
  if (fwrite(text, 1, len, console_log_file) != len || fflush(console_log_file) != 0)
    console_log_fail(errno);
}

/* Before the file opens: kept in memory, up to CONSOLE_LOG_EARLY_MAX bytes. */
static void console_log_keep(const char *text, size_t len) {
  if (console_log_early_dropped)
    return; /* what comes after a gap would read as if nothing were missing */
  if (console_log_early_len + len > console_log_early_cap) {
    size_t cap = 2 * console_log_early_cap + len + 4096;
    if (cap > CONSOLE_LOG_EARLY_MAX)
      cap = CONSOLE_LOG_EARLY_MAX;
    char *grown = console_log_early_len + len <= cap ? realloc(console_log_early, cap) : NULL;
    if (!grown) {
      console_log_early_dropped = 1;
      return;
    }
    console_log_early = grown;
    console_log_early_cap = cap;
  }
  memcpy(console_log_early + console_log_early_len, text, len);
  console_log_early_len += len;
}

static void console_log_add(const char *text) {
  if (console_log_failed || !console_log_previous)
    return;
  if (console_log_file)
    console_log_write(text, strlen(text));
  else
    console_log_keep(text, strlen(text));
}

static PetscErrorCode console_log_pass(FILE *fd, const char *format, ...) {
  va_list args;
  va_start(args, format);
  const PetscErrorCode ierr = console_log_previous(fd, format, args);
  va_end(args);
  return ierr;
}

/* The printer PETSc calls: formats once (PetscVSNPrintf, PETSc's conversions), hands the text
 * to the previous printer and copies what goes to the console. */
static PetscErrorCode console_log_print(FILE *fd, const char format[], va_list args) {
  char small[8192], *text = small;
  size_t full = 0;
  va_list again;
  PetscFunctionBeginUser;
  va_copy(again, args);
  PetscErrorCode ierr = PetscVSNPrintf(small, sizeof(small), format, &full, args);
  /* PetscVSNPrintf's full length leaves out the 4 marker bytes it adds around each %g (at
   * most one per 2 bytes of the format): room for them decides whether the text was cut */
  const size_t room = full + 2 * strlen(format) + 1;
  if (!ierr && room > sizeof(small)) {
    text = malloc(room);
    if (!text) {
      va_end(again);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory printing %zu bytes", room);
    }
    ierr = PetscVSNPrintf(text, room, format, NULL, again);
  }
  va_end(again);
  if (!ierr)
    ierr = console_log_pass(fd, "%s", text);
  if (!ierr && (fd == PETSC_STDOUT || fd == PETSC_STDERR || fd == stdout || fd == stderr))
    console_log_add(text);
  if (text != small)
    free(text);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode console_log_start(MPI_Comm comm) {
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0 || console_log_previous)
    PetscFunctionReturn(0);
  console_log_previous = PetscVFPrintf;
  PetscVFPrintf = console_log_print;
  PetscFunctionReturn(0);
}

/* ==== fresh run | restart from FILE at <UTC> (dmhs V, commit C, host H, pid P) ==== */
static PetscErrorCode console_log_opening_line(const char *restart_file, char *line, size_t len) {
  char host[256] = "unknown", when[32];
  const time_t now = time(NULL);
  struct tm utc;
  PetscFunctionBeginUser;
  PetscCheck(gmtime_r(&now, &utc) && strftime(when, sizeof(when), "%Y-%m-%dT%H:%M:%SZ", &utc),
             PETSC_COMM_SELF, PETSC_ERR_SYS, "cannot read the clock for %s", console_log_path);
  if (gethostname(host, sizeof(host)) != 0)
    snprintf(host, sizeof(host), "unknown");
  host[sizeof(host) - 1] = 0;
  snprintf(line, len, "==== %s%s at %s (dmhs %s, commit %s, host %s, pid %ld) ====\n",
           restart_file[0] ? "restart from " : "fresh run", restart_file, when, DMHS_VERSION,
           dmhs_commit, host, (long)getpid());
  PetscFunctionReturn(0);
}

PetscErrorCode console_log_open(const char *dir, const char *restart_file) {
  char line[PETSC_MAX_PATH_LEN + 512];
  PetscFunctionBeginUser;
  if (!console_log_previous || console_log_file || console_log_failed)
    PetscFunctionReturn(0); /* not rank 0, or already open */
  snprintf(console_log_path, sizeof(console_log_path), "%s/%s", dir, CONSOLE_LOG_NAME);
  PetscCall(console_log_opening_line(restart_file, line, sizeof(line)));
  /* a fresh run's log starts anew, as its other outputs do; a restart continues it */
  console_log_file = fopen(console_log_path, restart_file[0] ? "a" : "w");
  PetscCheck(console_log_file, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot open %s: %s",
             console_log_path, strerror(errno));
  console_log_write(line, strlen(line));
  if (console_log_file && console_log_early_len)
    console_log_write(console_log_early, console_log_early_len);
  if (console_log_file && console_log_early_dropped) {
    snprintf(line, sizeof(line),
             "(dmhs.log: the output before this line passed %d bytes and "
             "was cut)\n",
             CONSOLE_LOG_EARLY_MAX);
    console_log_write(line, strlen(line));
  }
  free(console_log_early);
  console_log_early = NULL;
  console_log_early_len = console_log_early_cap = 0;
  PetscFunctionReturn(0);
}

void console_log_add_line(const char *line) {
  if (console_log_file)
    console_log_add(line);
}

void console_log_stop(void) {
  if (!console_log_previous)
    return;
  PetscVFPrintf = console_log_previous;
  console_log_previous = NULL;
  if (console_log_file && fclose(console_log_file) != 0)
    fprintf(stderr, "dmhs: warning: cannot close %s: %s\n", console_log_path, strerror(errno));
  console_log_file = NULL;
  free(console_log_early);
  console_log_early = NULL;
  console_log_early_len = console_log_early_cap = 0;
}
