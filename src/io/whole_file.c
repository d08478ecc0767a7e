/* Files written whole or not at all (see whole_file.h). */
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include "dmhs/whole_file.h"

PetscErrorCode whole_file_open(whole_file *w, const char *path, const char *what) {
  const char *pre = what ? what : "", *sep = what ? ": " : "";
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(w->path, path, sizeof(w->path)));
  PetscCall(PetscSNPrintf(w->tmp, sizeof(w->tmp), "%s.tmp", path));
  w->f = fopen(w->tmp, "w");
  PetscCheck(w->f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s%scannot write %s: %s", pre, sep,
             w->tmp, strerror(errno));
  PetscFunctionReturn(0);
}

PetscErrorCode whole_file_commit(whole_file *w, int ok, const char *what) {
  const char *pre = what ? what : "", *sep = what ? ": " : "";
  PetscFunctionBeginUser;
  PetscCheck(w->f, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "%s is not open", w->tmp);
  ok = fclose(w->f) == 0 && ok;
  w->f = NULL;
  if (!ok)
    unlink(w->tmp);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s%swriting %s failed (disk full?)", pre,
             sep, w->tmp);
  PetscCheck(rename(w->tmp, w->path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "%s%scannot rename %s to %s: %s", pre, sep, w->tmp, w->path, strerror(errno));
  PetscFunctionReturn(0);
}
