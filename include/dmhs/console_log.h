/* <output_dir>/dmhs.log: a copy of everything rank 0 prints through PETSc (PetscPrintf,
 * PetscFPrintf to stdout or stderr, the viewers: the configuration, the stability report,
 * the progress lines, the end reports, -log_view) and of the error lines, so that a long
 * run's console survives the terminal or the batch system's log. src/io/console_log.c.
 *
 * PETSc prints through its function pointer PetscVFPrintf: console_log_start puts a copy in
 * front of the printer it finds there. Until the output directory exists, the copy is kept in
 * memory; console_log_open writes it to the file, and every later line goes there at once,
 * flushed, so a killed run's log is complete up to its last line. A fresh run starts the file
 * anew, a restart appends to it; each opening first writes a line
 *   ==== <fresh run | restart from FILE> at <ISO 8601 UTC> (dmhs V, commit C, host H, pid P) ====
 * A failed write (disk full) is said once on stderr and ends the copy, not the run. */
#ifndef DMHS_CONSOLE_LOG_H
#define DMHS_CONSOLE_LOG_H
#include <petscsys.h>

#define CONSOLE_LOG_NAME "dmhs.log"
/* What is kept in memory before the file opens, at most [bytes]; the rest is dropped. */
#define CONSOLE_LOG_EARLY_MAX (1 << 20)

/* After PetscInitialize: the copy, on rank 0 of comm (a no-op elsewhere). */
PetscErrorCode console_log_start(MPI_Comm comm);
/* Once dir exists (rank 0; a no-op elsewhere): opens dir/dmhs.log, anew for a fresh run
 * (restart_file "") or appending after a restart, writes the opening line and what was
 * kept. */
PetscErrorCode console_log_open(const char *dir, const char *restart_file);
/* A line printed outside PETSc (the error handler's), with its newline, added to the file if
 * it is open. Plain C: also on the error path. */
void console_log_add_line(const char *line);
/* After PetscFinalize: closes the file and gives PETSc its printer back. Plain C. */
void console_log_stop(void);

#endif
