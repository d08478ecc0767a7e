/* Stop signals (src/io/stop_signal.c): SIGTERM, SIGINT and SIGUSR1 ask the run
 * to write a checkpoint and stop at the next safe point (io_after_step).
 *
 * The handlers only record the first signal and stay installed: the same
 * request often arrives more than once (to every rank of a process group and
 * again through mpirun, a batch system's repeated notice, Ctrl-C pressed
 * twice), and a one-shot handler would let the second copy kill the run
 * before its checkpoint. A further signal kills (its default action) only
 * once the stop checkpoint is written, or STOP_SIGNAL_GRACE seconds after the
 * first signal (a run stuck before its checkpoint can still be killed), and
 * never within STOP_SIGNAL_ECHO seconds of the first: Open MPI's mpirun passes
 * SIGTERM and SIGINT on to the ranks a second late (odls_base_sigkill_timeout),
 * as SIGTERM, and that copy must not kill a run still writing its last files. */
#ifndef DMHS_STOP_SIGNAL_H
#define DMHS_STOP_SIGNAL_H
#include <petscsys.h>

/* Seconds after the first signal from which a further one kills, checkpoint or not. */
#define STOP_SIGNAL_GRACE 10.0
/* Seconds after the first signal within which a further one is a copy of it. */
#define STOP_SIGNAL_ECHO 2.0

/* Installs the handlers (again: a no-op). On rank 0 the first signal prints a
 * line saying the run will checkpoint and stop. */
PetscErrorCode stop_signal_install(PetscMPIInt rank);
/* The first stop signal this process received, 0 if none. */
int stop_signal_pending(void);
/* The stop checkpoint is written: from now on a further signal kills. */
void stop_signal_checkpoint_written(void);
/* "SIGTERM", "SIGINT", "SIGUSR1" or "a signal". */
const char *stop_signal_name(int sig);

#endif
