/* Stop signals (stop_signal.h): persistent handlers for SIGTERM, SIGINT and
 * SIGUSR1 that record the first one; a repeat is absorbed until the stop
 * checkpoint is written (and STOP_SIGNAL_ECHO seconds have passed) or
 * STOP_SIGNAL_GRACE seconds have passed, then kills.
 * The handler uses only async-signal-safe calls (clock_gettime, write,
 * sigaction, raise). */
#include <errno.h>
#include <signal.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "dmhs/stop_signal.h"

static volatile sig_atomic_t stop_first = 0;   /* the first signal's number */
static volatile sig_atomic_t stop_written = 0; /* the stop checkpoint is on disk */
static struct timespec stop_first_time;        /* written once, before stop_first */
static int stop_announce;                      /* rank 0 prints the notice */
static int stop_installed;

static const int stop_signals[] = {SIGTERM, SIGINT, SIGUSR1};

const char *stop_signal_name(int sig) {
  return sig == SIGTERM   ? "SIGTERM"
         : sig == SIGINT  ? "SIGINT"
         : sig == SIGUSR1 ? "SIGUSR1"
                          : "a signal";
}

static void stop_write(const char *text) {
  /* nothing to do if stderr is gone */
  ssize_t ignored = write(STDERR_FILENO, text, strlen(text));
  (void)ignored;
}

static void stop_on_signal(int sig) {
  const int saved_errno = errno; /* the interrupted code may be reading it */
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (!stop_first) {
    stop_first_time = now;
    stop_first = sig;
    if (stop_announce) {
      stop_write("dmhs: ");
      stop_write(stop_signal_name(sig));
      stop_write(" received: the run writes a checkpoint after this step and stops\n");
    }
  } else {
    const double since = (double)(now.tv_sec - stop_first_time.tv_sec) +
                         1e-9 * (double)(now.tv_nsec - stop_first_time.tv_nsec);
    if ((stop_written && since >= STOP_SIGNAL_ECHO) || since >= STOP_SIGNAL_GRACE) {
      /* the default action once this handler returns (the signal is blocked until then) */
      struct sigaction dfl;
      memset(&dfl, 0, sizeof(dfl));
      dfl.sa_handler = SIG_DFL;
      sigemptyset(&dfl.sa_mask);
      sigaction(sig, &dfl, NULL);
      raise(sig);
    }
  }
  errno = saved_errno;
}

PetscErrorCode stop_signal_install(PetscMPIInt rank) {
  struct sigaction sa;
  PetscFunctionBeginUser;
  stop_announce = rank == 0;
  if (stop_installed)
    PetscFunctionReturn(0);
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = stop_on_signal;
  sigemptyset(&sa.sa_mask);
  /* one handler at a time: a second signal waits for the first to be recorded */
  for (size_t k = 0; k < sizeof(stop_signals) / sizeof(stop_signals[0]); k++)
    sigaddset(&sa.sa_mask, stop_signals[k]);
  sa.sa_flags = SA_RESTART;
  for (size_t k = 0; k < sizeof(stop_signals) / sizeof(stop_signals[0]); k++)
    PetscCheck(sigaction(stop_signals[k], &sa, NULL) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
               "cannot install the %s handler: %s", stop_signal_name(stop_signals[k]),
               strerror(errno));
  stop_installed = 1;
  PetscFunctionReturn(0);
}

int stop_signal_pending(void) {
  return stop_first;
}

void stop_signal_checkpoint_written(void) {
  stop_written = 1;
}
