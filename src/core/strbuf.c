/* Appending to a fixed-size text buffer (see dmhs/strbuf.h). */
#include <string.h>
#include "dmhs/strbuf.h"

PetscErrorCode strbuf_cat(char *dst, size_t size, const char *src) {
  const size_t used = strnlen(dst, size), add = src ? strlen(src) : 0;
  PetscFunctionBeginUser;
  PetscCheck(used < size, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "text buffer of %zu bytes holds no terminated string", size);
  PetscCheck(add < size - used, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "text buffer of %zu bytes too small: %zu characters used, %zu more to append", size,
             used, add);
  if (add)
    memcpy(dst + used, src, add + 1);
  PetscFunctionReturn(0);
}
